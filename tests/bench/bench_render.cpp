// Rendering cost on the offscreen path (issue 9), in one run, as ratios:
//   - the mirror's reflection pass with the tight frustum (frustum::mirror =
//     reflect + oblique near plane, cropped to the mirror's screen
//     rectangle) versus a full-viewport reflection pass (frustum::reflect)
//     with a user clip plane (fragment discard), for a mirror rectangle
//     covering 1/16, 1/4 and 1/1 of a 1280x720 frame: time per pass and
//     fragments;
//   - N x N crop tiles (render::draw_tiled_frame) versus one full frame;
//   - the lens effect (render::draw_lens_frame, N x N lens tiles) versus its
//     per-pixel reference (reference::draw_lens_reference) and the plain frame,
//     and the CPU cost of the lens tiles;
//   - the CPU cost of a frame's matrix-pair updates, analytic versus
//     glm::inverse.
// Times: wall clock per frame, each frame ended with glFinish. The ratio
// tables come from paired frames (run_paired: every round draws each
// variant of a comparison once, in random order; median over rounds of the
// per-round ratio), so load from other processes on a shared machine hits
// both sides alike. Google Benchmark also runs every pass on its own
// (repetitions in random interleaved order; its JSON has the raw numbers)
// plus the CPU benchmarks. Fragment counts come from queries on an OSMesa
// (desktop GL) context: see FragmentCounts.
//
//   bench_render [--backend=egl|osmesa] [--out_dir=DIR] [--save_images=DIR] [--no_counts]
//                [--paired_seconds=S] [--lens_reference_4x] [benchmark flags]
//
// --paired_seconds: time budget per paired comparison (default 2; at least 9
// rounds). --lens_reference_4x: also the lens reference at 4x supersampling
// (seconds per frame on llvmpipe). Defaults: --benchmark_repetitions=5 --benchmark_min_time=0.05
// --benchmark_enable_random_interleaving=true
// --benchmark_display_aggregates_only=true (later flags override them).
// Writes DIR/render_summary.md and DIR/render_{mirror,tiles,lens}.dat (for
// scripts/plot-bench.sh) when --out_dir is given. Exits 1 if a GL object
// is still alive after teardown.
#include "bench_render_cpu.hpp"
#include "bench_render_setup.hpp"

#include <frustum/crop.hpp>
#include <frustum/lens.hpp>
#include <frustum/reflect.hpp>
#include <gl/objects.hpp>
#include <gl/offscreen_target.hpp>
#include <image/image.hpp>
#include <image/png.hpp>
#include <render/lens_pass.hpp>
#include <reference/lens_reference.hpp>
#include <render/mirror_pass.hpp>
#include <render/scene_pass.hpp>
#include <render/tile_pass.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <time.h>

namespace {

using namespace bench_render;

// ---------------------------------------------------------------- the passes

const scene::MirrorRect& mirror() { return *showcase().mirror; }

template <class T>
T checked(frustum::Result<T> result, const char* what) {
    if (!result) {
        throw std::runtime_error(std::string(what) + ": " + result.error());
    }
    return std::move(*result);
}

// The tight reflection pass, as render::draw_mirror_frame() draws it: plan
// (frustum::mirror + crop) every frame, then the scene without the mirror
// surface into a texture the size of the mirror's screen rectangle.
void draw_tight(const render::PassContext& ctx, const gl::OffscreenTarget& target, const MirrorCase& c,
                bool count_all) {
    const auto plan = plan::plan_reflection(mirror(), c.camera, kWidthPx, kHeightPx, plan::MirrorMethod::Oblique,
                                            showcase().world_bounds);
    if (!plan || !plan->has_value()) {
        throw std::runtime_error("no reflection for mirror case " + c.label);
    }
    target.bind();
    render::begin_frame(ctx);
    if (count_all) {
        ctx.fn.DepthFunc(GL_ALWAYS);
        ctx.fn.DepthMask(GL_FALSE);
    }
    render::SceneDraw draw((*plan)->pair);
    draw.skip_instance = mirror().instance;
    render::draw_scene(ctx, draw);
}

// The baseline: the reflected camera (frustum::reflect, no oblique plane,
// no crop) over the whole viewport; the clip plane discards fragments
// behind the mirror (scene.frag's CLIP_PLANE variant).
void draw_clip_plane(const render::PassContext& ctx, const gl::OffscreenTarget& target, const MirrorCase& c,
                     bool count_all) {
    const auto reflected = frustum::reflect(c.camera, c.plane);
    if (!reflected) {
        throw std::runtime_error(reflected.error());
    }
    target.bind();
    render::begin_frame(ctx);
    render::SceneDraw draw(*reflected);
    draw.skip_instance = mirror().instance;
    if (count_all) {
        ctx.fn.DepthFunc(GL_ALWAYS);
        ctx.fn.DepthMask(GL_FALSE);
    } else {
        draw.clip_plane = c.plane; // keeps the reflecting side: what lies in front of the mirror
    }
    render::draw_scene(ctx, draw);
}

void draw_full(const render::PassContext& ctx, const gl::OffscreenTarget& target,
               const frustum::MatrixPair<float>& camera, bool count_all) {
    target.bind();
    render::begin_frame(ctx);
    if (count_all) {
        ctx.fn.DepthFunc(GL_ALWAYS);
        ctx.fn.DepthMask(GL_FALSE);
    }
    render::draw_scene(ctx, render::SceneDraw(camera));
}

void draw_tiles(const render::PassContext& ctx, const gl::OffscreenTarget& target,
                const frustum::MatrixPair<float>& camera, int n) {
    if (auto status = render::draw_tiled_frame(ctx, target, camera, n, n); !status) {
        throw std::runtime_error(status.error());
    }
}

// A variant of draw_tiled_frame() for tiles that share one target: one
// unscissored clear of the whole frame, then each tile only draws. (A
// scissored clear that is not the whole surface is drawn as a quad by Mesa,
// with a fragment shader over every pixel of the tile.)
void draw_tiles_one_clear(const render::PassContext& ctx, const gl::OffscreenTarget& target,
                          const frustum::MatrixPair<float>& camera, int n) {
    const auto tiles = frustum::crop_tiles(camera, kWidthPx, kHeightPx, n, n);
    if (!tiles) {
        throw std::runtime_error(tiles.error());
    }
    target.bind();
    render::begin_frame(ctx);
    ctx.fn.Enable(GL_SCISSOR_TEST);
    for (const auto& tile : *tiles) {
        ctx.fn.Viewport(tile.x_px, tile.y_px, tile.width_px, tile.height_px);
        ctx.fn.Scissor(tile.x_px, tile.y_px, tile.width_px, tile.height_px);
        render::draw_scene(ctx, render::SceneDraw(tile.pair));
    }
    ctx.fn.Disable(GL_SCISSOR_TEST);
    target.bind();
}

// The lens effect as Renderer draws it (render::draw_lens_frame: lens_tiles
// with refitted far planes, a scissored clear + scene per tile).
void draw_lens(const render::PassContext& ctx, const gl::OffscreenTarget& target, const render::LensDraw& draw) {
    if (auto status = render::draw_lens_frame(ctx, target, draw); !status) {
        throw std::runtime_error(status.error());
    }
}

// Its per-pixel reference (reference::draw_lens_reference: the unwarped view
// into nested textures at `supersampling` x the frame's resolution, then
// eq. 34 per pixel as a texture remap).
void draw_lens_ref(const render::PassContext& ctx, const gl::OffscreenTarget& target,
                         const render::LensDraw& draw, int supersampling) {
    if (auto levels = reference::draw_lens_reference(ctx, target, draw, supersampling); !levels) {
        throw std::runtime_error(levels.error());
    }
}

// The plain frame the lens pass starts from (lens disc hidden).
void draw_lens_plain(const render::PassContext& ctx, const gl::OffscreenTarget& target, const render::LensDraw& draw,
                     bool count_all) {
    target.bind();
    render::begin_frame(ctx);
    if (count_all) {
        ctx.fn.DepthFunc(GL_ALWAYS);
        ctx.fn.DepthMask(GL_FALSE);
    }
    render::SceneDraw scene(draw.camera);
    scene.skip_instance = draw.skip_instance;
    render::draw_scene(ctx, scene);
}

// Reference texture resolution / frame resolution: 1 by default; 4 (what
// frustum-demo lens-report compares against) with --lens_reference_4x, as it
// takes seconds per frame on llvmpipe.
std::vector<int> g_lens_supersampling{1};

std::string g_save_dir; // --save_images=DIR: the counted passes as PNGs, to check by eye

void save(const gl::OffscreenTarget& target, const std::string& name) {
    if (g_save_dir.empty()) {
        return;
    }
    const image::Image picture = checked(target.read_rgba8(), "read");
    if (auto status = image::write_png(picture, g_save_dir + "/" + name + ".png"); !status) {
        throw std::runtime_error(status.error());
    }
}

gl::OffscreenTarget make_target(const Gpu& gpu, int width, int height) {
    return checked(gl::OffscreenTarget::create(*gpu.fn, {width, height, gl::ColorStorage::Texture,
                                                         gl::DepthFormat::Depth24}),
                   "OffscreenTarget");
}

// ---------------------------------------------------------------- counts

struct MirrorCounts {
    FragmentCounts tight, clip;
    long compared = 0, over = 0; // rectangle pixels, of which differ by > 2 LSB between the two
};

struct Counts {
    std::vector<MirrorCounts> mirrors;
    FragmentCounts full;
    std::map<int, FragmentCounts> tiles, tiles_one_clear;
    FragmentCounts lens_plain;
    std::map<int, FragmentCounts> lens, lens_reference; // by grid / by supersampling
    std::map<int, int> lens_reference_levels;           // nested textures the reference needed
    std::string context;
};

// The tight texture against the same rectangle of the baseline's frame: the
// two passes must draw the same reflection for the comparison to be fair.
void compare_reflections(const gl::OffscreenTarget& tight, const gl::OffscreenTarget& full, const MirrorCase& c,
                         MirrorCounts& out) {
    const image::Image a = checked(tight.read_rgba8(), "read tight");
    const image::Image b = checked(full.read_rgba8(), "read full");
    for (int y = 0; y < a.height; ++y) { // rows top to bottom in both images
        for (int x = 0; x < a.width; ++x) {
            const auto pa = image::pixel_at(a, x, y);
            const auto pb = image::pixel_at(b, c.rect.x + x, kHeightPx - (c.rect.y + c.rect.height) + y);
            int d = 0;
            for (int k = 0; k < 3; ++k) {
                d = std::max(d, std::abs(int(pa[k]) - int(pb[k])));
            }
            ++out.compared;
            out.over += d > 2 ? 1 : 0;
        }
    }
}

Counts count_everything(const std::vector<MirrorCase>& cases, std::string& why) {
    Counts counts;
    auto gpu = make_gpu(gl::Backend::OsMesa, why);
    if (!gpu) {
        return counts;
    }
    counts.context = gl::summary(gpu->context->describe());
    const render::PassContext ctx = gpu->pass();
    const auto full = make_target(*gpu, kWidthPx, kHeightPx);
    for (const MirrorCase& c : cases) {
        const auto tight = make_target(*gpu, c.rect.width, c.rect.height);
        MirrorCounts m;
        m.tight = count_fragments(*gpu, [&](bool all) { draw_tight(ctx, tight, c, all); });
        m.clip = count_fragments(*gpu, [&](bool all) { draw_clip_plane(ctx, full, c, all); });
        // Count passes end with the count_all draw: draw both for real again.
        draw_tight(ctx, tight, c, false);
        draw_clip_plane(ctx, full, c, false);
        compare_reflections(tight, full, c, m);
        save(tight, "mirror-" + std::to_string(counts.mirrors.size()) + "-tight");
        save(full, "mirror-" + std::to_string(counts.mirrors.size()) + "-clip-plane");
        counts.mirrors.push_back(m);
    }
    const auto camera = main_camera();
    counts.full = count_fragments(*gpu, [&](bool all) { draw_full(ctx, full, camera, all); });
    draw_full(ctx, full, camera, false);
    save(full, "full");
    // The tile passes set their own depth state: the real pass only.
    for (int n : kCropTileCounts) {
        auto f = count_fragments(*gpu, [&](bool) { draw_tiles(ctx, full, camera, n); });
        f.rasterized = -1;
        counts.tiles[n] = f;
        save(full, "tiles-" + std::to_string(n));
        f = count_fragments(*gpu, [&](bool) { draw_tiles_one_clear(ctx, full, camera, n); });
        f.rasterized = -1;
        counts.tiles_one_clear[n] = f;
    }
    // The lens passes draw several targets and set their own state: real passes only.
    counts.lens_plain = count_fragments(*gpu, [&](bool all) { draw_lens_plain(ctx, full, lens_draw(1), all); });
    for (int n : kLensTileCounts) {
        auto f = count_fragments(*gpu, [&](bool) { draw_lens(ctx, full, lens_draw(n)); });
        f.rasterized = -1;
        counts.lens[n] = f;
        save(full, "lens-" + std::to_string(n));
    }
    for (int k : g_lens_supersampling) {
        auto f = count_fragments(*gpu, [&](bool) { draw_lens_ref(ctx, full, lens_draw(1), k); });
        f.rasterized = -1;
        counts.lens_reference[k] = f;
        counts.lens_reference_levels[k] = checked(reference::draw_lens_reference(ctx, full, lens_draw(1), k), "levels");
        save(full, "lens-reference-" + std::to_string(k));
    }
    return counts;
}

// ---------------------------------------------------------------- timing

// Everything the GPU benchmarks draw with, alive from registration to teardown.
struct Timing {
    std::unique_ptr<Gpu> gpu;
    std::vector<MirrorCase> cases;
    std::vector<gl::OffscreenTarget> tight_targets;
    std::optional<gl::OffscreenTarget> full, frame;
    frustum::MatrixPair<float> camera = main_camera();
    std::map<std::string, std::function<void()>> draws; // by benchmark name
};
Timing* timing = nullptr;

void register_gpu(const std::string& name, std::function<void()> draw) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [draw](benchmark::State& state) {
                                     const gl::Functions& fn = *timing->gpu->fn;
                                     for (auto _ : state) {
                                         draw();
                                         fn.Finish();
                                     }
                                 })
        ->UseRealTime()
        ->MeasureProcessCPUTime()
        ->Unit(benchmark::kMillisecond);
    timing->draws[name] = draw;
    draw(); // warm up: llvmpipe compiles shader variants on first use
    timing->gpu->fn->Finish();
}

void register_gpu_benchmarks(Timing& t) {
    const render::PassContext ctx = t.gpu->pass();
    for (std::size_t i = 0; i < t.cases.size(); ++i) {
        const MirrorCase* c = &t.cases[i];
        const gl::OffscreenTarget* tight = &t.tight_targets[i];
        const gl::OffscreenTarget* full = &*t.full;
        const std::string prefix = "mirror/" + c->label + "/";
        register_gpu(prefix + "tight", [ctx, tight, c] { draw_tight(ctx, *tight, *c, false); });
        register_gpu(prefix + "clip_plane", [ctx, full, c] { draw_clip_plane(ctx, *full, *c, false); });
        register_gpu(prefix + "main_pass", [ctx, full, c] { draw_full(ctx, *full, c->camera, false); });
        // The renderer's whole mirror frame (main pass + tight reflection
        // into a new texture + composite), for scale.
        const gl::OffscreenTarget* frame = &*t.frame;
        register_gpu(prefix + "renderer_frame", [ctx, frame, c] {
            const render::MirrorDraw draw{c->camera, mirror(), plan::MirrorMethod::Oblique,
                                          glm::vec3(0.92f, 0.95f, 1.0f), showcase().world_bounds};
            if (auto status = render::draw_mirror_frame(ctx, *frame, draw); !status) {
                throw std::runtime_error(status.error());
            }
        });
    }
    const gl::OffscreenTarget* full = &*t.full;
    const frustum::MatrixPair<float> camera = t.camera;
    register_gpu("tiles/full", [ctx, full, camera] { draw_full(ctx, *full, camera, false); });
    for (int n : kCropTileCounts) {
        register_gpu("tiles/" + std::to_string(n) + "x" + std::to_string(n),
                     [ctx, full, camera, n] { draw_tiles(ctx, *full, camera, n); });
        register_gpu("tiles_one_clear/" + std::to_string(n) + "x" + std::to_string(n),
                     [ctx, full, camera, n] { draw_tiles_one_clear(ctx, *full, camera, n); });
    }
    const render::LensDraw lens = lens_draw(1);
    register_gpu("lens/plain", [ctx, full, lens] { draw_lens_plain(ctx, *full, lens, false); });
    for (int k : g_lens_supersampling) {
        // Paired rounds only for the slow 4x reference (Google Benchmark would repeat it 5 times more).
        const std::string name = "lens/reference_" + std::to_string(k) + "x";
        auto draw = [ctx, full, lens, k] { draw_lens_ref(ctx, *full, lens, k); };
        if (k == 1) {
            register_gpu(name, draw);
        } else {
            timing->draws[name] = draw;
        }
    }
    for (int n : kLensTileCounts) {
        const render::LensDraw tiled = lens_draw(n);
        register_gpu("lens/" + std::to_string(n) + "x" + std::to_string(n),
                     [ctx, full, tiled] { draw_lens(ctx, *full, tiled); });
    }
}

// Side by side, frame by frame: each round draws every variant of a group
// once, in a new random order, each frame timed on its own (wall clock and
// process CPU time, glFinish included). Ratios are medians over the rounds
// of variant / names[0] within the same round, so load from other processes
// that drifts over seconds cancels out.
struct Paired {
    std::vector<std::string> names;            // names[0]: the reference
    std::vector<double> wall_ms, cpu_ms;       // median per variant
    std::vector<double> wall_ratio, cpu_ratio; // median over rounds of variant / names[0]
    int rounds = 0;
    std::vector<std::vector<double>> wall, cpu; // [variant][round], ms

    // Median over rounds of variant a / variant b (wall or CPU time).
    double ratio(std::size_t a, std::size_t b, bool use_cpu) const;
};

double process_cpu_s() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median(std::vector<double> v) {
    if (v.empty()) {
        return NAN;
    }
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double Paired::ratio(std::size_t a, std::size_t b, bool use_cpu) const {
    const auto& x = use_cpu ? cpu : wall;
    std::vector<double> r;
    for (std::size_t i = 0; i < x[a].size(); ++i) {
        r.push_back(x[a][i] / x[b][i]);
    }
    return median(r);
}

Paired run_paired(const Timing& t, const std::vector<std::string>& names, double budget_s, std::mt19937& rng) {
    const gl::Functions& fn = *t.gpu->fn;
    const std::size_t n = names.size();
    std::vector<const std::function<void()>*> draws;
    for (const std::string& name : names) {
        draws.push_back(&t.draws.at(name));
        (*draws.back())(); // warm up
        fn.Finish();
    }
    std::vector<std::vector<double>> wall(n), cpu(n), wall_ratio(n), cpu_ratio(n);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) {
        order[i] = i;
    }
    constexpr int kMinRounds = 9, kMaxRounds = 201;
    const auto start = std::chrono::steady_clock::now();
    Paired out;
    out.names = names;
    while (out.rounds < kMaxRounds &&
           (out.rounds < kMinRounds ||
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < budget_s)) {
        std::shuffle(order.begin(), order.end(), rng);
        std::vector<double> w(n), c(n);
        for (std::size_t i : order) {
            const double c0 = process_cpu_s();
            const auto w0 = std::chrono::steady_clock::now();
            (*draws[i])();
            fn.Finish();
            w[i] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count();
            c[i] = 1000.0 * (process_cpu_s() - c0);
        }
        for (std::size_t i = 0; i < n; ++i) {
            wall[i].push_back(w[i]);
            cpu[i].push_back(c[i]);
            wall_ratio[i].push_back(w[i] / w[0]);
            cpu_ratio[i].push_back(c[i] / c[0]);
        }
        ++out.rounds;
    }
    for (std::size_t i = 0; i < n; ++i) {
        out.wall_ms.push_back(median(wall[i]));
        out.cpu_ms.push_back(median(cpu[i]));
        out.wall_ratio.push_back(median(wall_ratio[i]));
        out.cpu_ratio.push_back(median(cpu_ratio[i]));
    }
    out.wall = std::move(wall);
    out.cpu = std::move(cpu);
    return out;
}

// Group name -> result: "mirror/1/4" = {tight, clip_plane}; "tiles/4x4" =
// {full, draw_tiled_frame, one clear}.
using PairedResults = std::map<std::string, Paired>;

PairedResults run_all_paired(const Timing& t, double budget_s) {
    PairedResults out;
    if (!(budget_s > 0.0)) {
        return out;
    }
    std::mt19937 rng(12345u);
    for (const MirrorCase& c : t.cases) {
        const std::string p = "mirror/" + c.label;
        out[p] = run_paired(t, {p + "/tight", p + "/clip_plane"}, budget_s, rng);
        std::cerr << "paired " << p << ": " << out[p].rounds << " rounds\n";
    }
    for (int n : kCropTileCounts) {
        const std::string nn = std::to_string(n) + "x" + std::to_string(n);
        out["tiles/" + nn] = run_paired(t, {"tiles/full", "tiles/" + nn, "tiles_one_clear/" + nn}, budget_s, rng);
        std::cerr << "paired tiles/" << nn << ": " << out["tiles/" + nn].rounds << " rounds\n";
    }
    std::vector<std::string> lens{"lens/plain"};
    for (int k : g_lens_supersampling) {
        lens.push_back("lens/reference_" + std::to_string(k) + "x");
    }
    for (int n : kLensTileCounts) {
        lens.push_back("lens/" + std::to_string(n) + "x" + std::to_string(n));
    }
    out["lens"] = run_paired(t, lens, budget_s, rng);
    std::cerr << "paired lens: " << out["lens"].rounds << " rounds\n";
    return out;
}

// ---------------------------------------------------------------- reporting

// Keeps, per benchmark, the median wall time and the median process CPU time
// (all threads: llvmpipe rasterizes on its own threads) per iteration, in
// ms, and the wall time's coefficient of variation.
class Collector : public benchmark::ConsoleReporter {
public:
    struct Stat {
        double wall_ms = NAN, cpu_ms = NAN, cv = NAN;
        std::vector<double> wall_runs, cpu_runs;
    };
    std::map<std::string, Stat> stats;

    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            if (r.error_occurred) {
                continue;
            }
            std::string name = r.run_name.str();
            for (const char* suffix : {"/process_time", "/real_time"}) {
                if (const auto at = name.find(suffix); at != std::string::npos) {
                    name.erase(at, std::string(suffix).size());
                }
            }
            Stat& s = stats[name];
            if (r.run_type == Run::RT_Aggregate) {
                if (r.aggregate_name == "median") {
                    s.wall_ms = r.GetAdjustedRealTime() / per_ms(r.time_unit);
                    s.cpu_ms = r.GetAdjustedCPUTime() / per_ms(r.time_unit);
                } else if (r.aggregate_name == "cv") {
                    s.cv = r.real_accumulated_time; // a ratio, not a time
                }
            } else {
                s.wall_runs.push_back(r.GetAdjustedRealTime() / per_ms(r.time_unit));
                s.cpu_runs.push_back(r.GetAdjustedCPUTime() / per_ms(r.time_unit));
            }
        }
        ConsoleReporter::ReportRuns(runs);
    }

    // Median wall time per iteration: the aggregate, else of the runs seen.
    double ms(const std::string& name) const { return pick(name, &Stat::wall_ms, &Stat::wall_runs); }
    // Median process CPU time per iteration (every thread of the process).
    double cpu_ms(const std::string& name) const { return pick(name, &Stat::cpu_ms, &Stat::cpu_runs); }

    std::string cv(const std::string& name) const {
        const auto it = stats.find(name);
        if (it == stats.end() || std::isnan(it->second.cv)) {
            return "";
        }
        return " ±" + fixed(100.0 * it->second.cv, 0) + "%";
    }
    static std::string fixed(double v, int digits) {
        if (std::isnan(v)) {
            return "n/a";
        }
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
        return buffer;
    }

private:
    double pick(const std::string& name, double Stat::*median, std::vector<double> Stat::*runs) const {
        const auto it = stats.find(name);
        if (it == stats.end()) {
            return NAN;
        }
        if (!std::isnan(it->second.*median)) {
            return it->second.*median;
        }
        std::vector<double> v = it->second.*runs;
        if (v.empty()) {
            return NAN;
        }
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    }
    static double per_ms(benchmark::TimeUnit unit) {
        switch (unit) {
        case benchmark::kNanosecond: return 1e6;
        case benchmark::kMicrosecond: return 1e3;
        case benchmark::kMillisecond: return 1.0;
        case benchmark::kSecond: return 1e-3;
        }
        return 1.0;
    }
};

std::string count_text(std::int64_t v) { return v < 0 ? "n/a" : std::to_string(v); }
std::string ratio_text(double a, double b, int digits = 2) {
    return (std::isnan(a) || std::isnan(b) || b == 0.0) ? "n/a" : Collector::fixed(a / b, digits) + "x";
}
double as_double(std::int64_t v) { return v < 0 ? NAN : double(v); }

// "12.34" from a paired median, or "n/a".
const Paired* find(const PairedResults& paired, const std::string& group) {
    const auto it = paired.find(group);
    return it == paired.end() ? nullptr : &it->second;
}
std::string times(double v) { return std::isnan(v) ? "n/a" : Collector::fixed(v, 2) + "x"; }

std::string scene_summary() {
    const scene::Scene& s = showcase();
    long draws = 0, triangles = 0;
    for (const scene::Instance& instance : s.instances) {
        for (const scene::Primitive& primitive : s.meshes[static_cast<std::size_t>(instance.mesh)].primitives) {
            ++draws;
            if (primitive.mode == scene::PrimitiveMode::Triangles) {
                triangles += static_cast<long>(primitive.indices.size() / 3);
            }
        }
    }
    return "assets/showcase.gltf: " + std::to_string(s.instances.size()) + " instances, " + std::to_string(draws) +
           " draw calls and " + std::to_string(triangles) + " triangles per scene pass";
}

std::string report(const Collector& col, const PairedResults& paired, const std::vector<MirrorCase>& cases,
                   const Counts& counts, bool have_counts, const std::string& timing_context) {
    using C = Collector;
    std::ostringstream md;
    md << "Timing context: " << timing_context << "\n";
    md << "Counting context: " << (have_counts ? counts.context : std::string("none (no OSMesa)")) << "\n";
    md << "Scene: " << scene_summary() << "\n\n";

    md << "### Reflection pass: tight frustum vs full viewport + clip plane (1280x720)\n\n";
    md << "| mirror rect | rect px | distance m | tight ms | clip-plane ms | clip/tight | clip/tight (CPU) | rounds "
          "| main pass ms | renderer mirror frame ms |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const MirrorCase& c : cases) {
        const std::string p = "mirror/" + c.label;
        const Paired* r = find(paired, p);
        md << "| " << c.label << " (" << C::fixed(100.0 * c.coverage, 1) << "%) | " << c.rect.width << "x"
           << c.rect.height << " | " << C::fixed(c.distance_m, 2) << " | ";
        if (r) {
            md << C::fixed(r->wall_ms[0], 2) << " | " << C::fixed(r->wall_ms[1], 2) << " | " << times(r->wall_ratio[1])
               << " | " << times(r->cpu_ratio[1]) << " | " << r->rounds << " | ";
        } else {
            md << "n/a | n/a | n/a | n/a | 0 | ";
        }
        md << C::fixed(col.ms(p + "/main_pass"), 2) << " | " << C::fixed(col.ms(p + "/renderer_frame"), 2) << " |\n";
    }
    if (have_counts) {
        md << "\n| mirror rect | rasterized tight | rasterized clip-plane | ratio | FS invocations tight | FS "
              "invocations clip-plane | ratio | written tight | written clip-plane | same picture |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n";
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const MirrorCounts& m = counts.mirrors[i];
            md << "| " << cases[i].label << " | " << count_text(m.tight.rasterized) << " | "
               << count_text(m.clip.rasterized) << " | "
               << ratio_text(as_double(m.clip.rasterized), as_double(m.tight.rasterized)) << " | "
               << count_text(m.tight.fs_invocations) << " | " << count_text(m.clip.fs_invocations) << " | "
               << ratio_text(as_double(m.clip.fs_invocations), as_double(m.tight.fs_invocations)) << " | "
               << count_text(m.tight.written) << " | " << count_text(m.clip.written) << " | " << m.over << " of "
               << m.compared << " px differ > 2 LSB |\n";
        }
    }

    md << "\n### N x N crop tiles vs one full frame (1280x720)\n\n";
    md << "| tiles | full frame ms | draw_tiled_frame ms | tiles/full | tiles/full (CPU) | FS invocations vs full "
          "| one clear ms | tiles/full | tiles/full (CPU) | FS invocations vs full | rounds |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (int n : kCropTileCounts) {
        const std::string nn = std::to_string(n) + "x" + std::to_string(n);
        const Paired* r = find(paired, "tiles/" + nn);
        const FragmentCounts f = have_counts ? counts.tiles.at(n) : FragmentCounts{};
        const FragmentCounts g = have_counts ? counts.tiles_one_clear.at(n) : FragmentCounts{};
        const double full_fs = as_double(counts.full.fs_invocations);
        if (!r) {
            continue;
        }
        md << "| " << nn << " | " << C::fixed(r->wall_ms[0], 2) << " | " << C::fixed(r->wall_ms[1], 2) << " | "
           << times(r->wall_ratio[1]) << " | " << times(r->cpu_ratio[1]) << " | "
           << ratio_text(as_double(f.fs_invocations), full_fs, 3) << " | " << C::fixed(r->wall_ms[2], 2) << " | "
           << times(r->wall_ratio[2]) << " | " << times(r->cpu_ratio[2]) << " | "
           << ratio_text(as_double(g.fs_invocations), full_fs, 3) << " | " << r->rounds << " |\n";
    }
    md << "\n### Lens (render::draw_lens_frame, N x N tiles) vs its per-pixel reference (1280x720)\n\n";
    if (const Paired* r = find(paired, "lens")) {
        const std::size_t kRef = 1; // the per-pixel reference at the frame's resolution
        md << "| variant | ms | vs reference 1x | vs reference 1x (CPU) | vs plain frame | vs plain (CPU) | FS "
              "invocations vs plain |\n|---|---|---|---|---|---|---|\n";
        for (std::size_t i = 0; i < r->names.size(); ++i) {
            const std::string& name = r->names[i];
            FragmentCounts f;
            if (have_counts) {
                if (name == "lens/plain") {
                    f = counts.lens_plain;
                }
                for (int k : g_lens_supersampling) {
                    if (name == "lens/reference_" + std::to_string(k) + "x") {
                        f = counts.lens_reference.at(k);
                    }
                }
                for (int n : kLensTileCounts) {
                    if (name == "lens/" + std::to_string(n) + "x" + std::to_string(n)) {
                        f = counts.lens.at(n);
                    }
                }
            }
            md << "| " << name.substr(5) << " | " << C::fixed(r->wall_ms[i], 2) << " | " << times(r->ratio(i, kRef, false))
               << " | " << times(r->ratio(i, kRef, true)) << " | " << times(r->ratio(i, 0, false)) << " | "
               << times(r->ratio(i, 0, true)) << " | "
               << ratio_text(as_double(f.fs_invocations), as_double(counts.lens_plain.fs_invocations), 2) << " |\n";
        }
        md << "\n(" << r->rounds << " paired rounds. Nested levels the reference rendered:";
        for (const auto& [k, levels] : counts.lens_reference_levels) {
            md << " " << levels << " at " << k << "x" << (k == counts.lens_reference_levels.rbegin()->first ? "" : ",");
        }
        md << ".)\n";
    }
    md << "\n| tiles | frustum::lens_tiles CPU us | per tile us |\n|---|---|---|\n";
    for (int n : kLensTileCounts) {
        const std::string nn = std::to_string(n) + "x" + std::to_string(n);
        const double us = 1000.0 * col.ms("cpu/lens_tiles/" + nn);
        md << "| " << nn << " | " << C::fixed(us, 1) << col.cv("cpu/lens_tiles/" + nn) << " | "
           << C::fixed(us / (n * n), 2) << " |\n";
    }
    md << "\n### CPU: one frame's matrix-pair updates (camera + mirror + crop + 4x4 tiles = 19 pairs)\n\n";
    const double a = col.ms("cpu/frame_updates/analytic"), g = col.ms("cpu/frame_updates/glm_inverse");
    md << "| analytic us | glm::inverse us | glm::inverse / analytic |\n|---|---|---|\n| "
       << C::fixed(1000.0 * a, 2) << col.cv("cpu/frame_updates/analytic") << " | " << C::fixed(1000.0 * g, 2)
       << col.cv("cpu/frame_updates/glm_inverse") << " | " << ratio_text(g, a) << " |\n";
    md << "\n(Mirror and tile tables: paired frames, see run_paired(): ms = median wall time per frame, glFinish "
          "included; ratios = median over rounds of the per-round ratio; (CPU) = the same with the whole "
          "process's CPU time, llvmpipe's threads included, less sensitive to other load. Other columns: Google "
          "Benchmark medians; ± = coefficient of variation over its repetitions.)\n";
    return md.str();
}

void write_data(const std::string& dir, const Collector& col, const PairedResults& paired,
                const std::vector<MirrorCase>& cases, const Counts& counts, bool have_counts) {
    std::ofstream mirror_dat(dir + "/render_mirror.dat");
    mirror_dat << "# coverage tight_ms clip_plane_ms rasterized_tight rasterized_clip fs_tight fs_clip label "
                  "tight_cpu_ms clip_plane_cpu_ms ratio_wall ratio_cpu\n";
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Paired* r = find(paired, "mirror/" + cases[i].label);
        const MirrorCounts m = have_counts ? counts.mirrors[i] : MirrorCounts{};
        if (!r) {
            continue;
        }
        mirror_dat << cases[i].coverage << ' ' << r->wall_ms[0] << ' ' << r->wall_ms[1] << ' ' << m.tight.rasterized
                   << ' ' << m.clip.rasterized << ' ' << m.tight.fs_invocations << ' ' << m.clip.fs_invocations << ' '
                   << cases[i].label << ' ' << r->cpu_ms[0] << ' ' << r->cpu_ms[1] << ' ' << r->wall_ratio[1] << ' '
                   << r->cpu_ratio[1] << '\n';
    }
    std::ofstream tiles_dat(dir + "/render_tiles.dat");
    tiles_dat << "# tiles_per_side tile_count tiles_ms full_ms one_clear_ms ratio_wall ratio_cpu "
                 "one_clear_ratio_wall one_clear_ratio_cpu\n";
    for (int n : kCropTileCounts) {
        const Paired* r = find(paired, "tiles/" + std::to_string(n) + "x" + std::to_string(n));
        if (!r) {
            continue;
        }
        tiles_dat << n << ' ' << n * n << ' ' << r->wall_ms[1] << ' ' << r->wall_ms[0] << ' ' << r->wall_ms[2] << ' '
                  << r->wall_ratio[1] << ' ' << r->cpu_ratio[1] << ' ' << r->wall_ratio[2] << ' ' << r->cpu_ratio[2]
                  << '\n';
    }
    std::ofstream lens_dat(dir + "/render_lens.dat");
    lens_dat << "# tiles_per_side tile_count lens_ms plain_ms ratio_vs_plain_wall ratio_vs_plain_cpu "
                "ratio_vs_ref1_wall ratio_vs_ref1_cpu ref1_vs_plain_wall ref4_vs_plain_wall lens_tiles_cpu_us\n";
    if (const Paired* r = find(paired, "lens")) {
        const std::size_t first_tiles = 1 + g_lens_supersampling.size();
        const std::size_t ref4 = g_lens_supersampling.size() > 1 ? 2 : 1;
        for (std::size_t i = first_tiles; i < r->names.size(); ++i) {
            const int n = kLensTileCounts[i - first_tiles];
            lens_dat << n << ' ' << n * n << ' ' << r->wall_ms[i] << ' ' << r->wall_ms[0] << ' ' << r->ratio(i, 0, false)
                     << ' ' << r->ratio(i, 0, true) << ' ' << r->ratio(i, 1, false) << ' ' << r->ratio(i, 1, true)
                     << ' ' << r->ratio(1, 0, false) << ' ' << r->ratio(ref4, 0, false) << ' '
                     << 1000.0 * col.ms("cpu/lens_tiles/" + std::to_string(n) + "x" + std::to_string(n)) << '\n';
        }
    }
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) == 0) {
            return line.substr(line.find(':') + 2);
        }
    }
    return "unknown CPU";
}

int run(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--cpu_frame_table" || std::string(argv[i]) == "--dump_frame_scene") {
            return run_cpu_frame_table(argc, argv); // no GL context
        }
    }
    gl::Backend backend = gl::Backend::Egl;
    std::string out_dir;
    bool counts_wanted = true;
    double paired_budget_s = 2.0;
    std::vector<char*> args{argv[0]};
    static char defaults[][64] = {"--benchmark_repetitions=5", "--benchmark_min_time=0.05",
                                  "--benchmark_enable_random_interleaving=true",
                                  "--benchmark_display_aggregates_only=true"};
    for (auto& d : defaults) {
        args.push_back(d);
    }
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a.rfind("--backend=", 0) == 0) {
            backend = checked(gl::parse_backend(a.substr(10)), "--backend");
        } else if (a.rfind("--out_dir=", 0) == 0) {
            out_dir = a.substr(10);
        } else if (a.rfind("--save_images=", 0) == 0) {
            g_save_dir = a.substr(14);
        } else if (a.rfind("--paired_seconds=", 0) == 0) {
            paired_budget_s = std::stod(a.substr(17));
        } else if (a == "--lens_reference_4x") {
            g_lens_supersampling = {1, 4};
        } else if (a == "--no_counts") {
            counts_wanted = false;
        } else {
            args.push_back(argv[i]);
        }
    }
    int bench_argc = static_cast<int>(args.size());
    benchmark::Initialize(&bench_argc, args.data());
    if (benchmark::ReportUnrecognizedArguments(bench_argc, args.data())) {
        return 2;
    }

    std::vector<MirrorCase> cases;
    for (const auto& [label, fraction] : {std::pair<const char*, double>{"1/16", 1.0 / 16}, {"1/4", 0.25}, {"1/1", 1.0}}) {
        cases.push_back(make_mirror_case(label, fraction));
    }

    Counts counts;
    bool have_counts = false;
    if (counts_wanted) {
        std::string why;
        counts = count_everything(cases, why);
        have_counts = !counts.context.empty();
        std::cerr << (have_counts ? "fragment counts: " + counts.context : "no fragment counts: " + why) << "\n";
    }

    std::string why;
    auto gpu = make_gpu(backend, why);
    if (!gpu) {
        std::cerr << "bench_render: no " << gl::to_string(backend) << " context: " << why << "\n";
        return 1;
    }
    const std::string timing_context = gl::summary(gpu->context->describe()) + " | CPU: " + cpu_model();
    std::cerr << "timing: " << timing_context << "\n";
    {
        Timing t;
        t.gpu = std::move(gpu);
        t.cases = cases;
        for (const MirrorCase& c : t.cases) {
            t.tight_targets.push_back(make_target(*t.gpu, c.rect.width, c.rect.height));
        }
        t.full.emplace(make_target(*t.gpu, kWidthPx, kHeightPx));
        t.frame.emplace(checked(gl::OffscreenTarget::create(*t.gpu->fn, {kWidthPx, kHeightPx}), "frame"));
        timing = &t;
        register_gpu_benchmarks(t);
        register_cpu_benchmarks();
        register_cpu_frame_benchmarks();

        Collector collector;
        benchmark::RunSpecifiedBenchmarks(&collector);
        benchmark::Shutdown();
        const PairedResults paired = run_all_paired(t, paired_budget_s);

        const std::string md = report(collector, paired, cases, counts, have_counts, timing_context);
        std::cout << "\n" << md;
        if (!out_dir.empty()) {
            std::ofstream(out_dir + "/render_summary.md") << md;
            write_data(out_dir, collector, paired, cases, counts, have_counts);
        }
        // Teardown in order: targets, renderer, table, context.
        t.tight_targets.clear();
        t.full.reset();
        t.frame.reset();
        t.gpu.reset();
        timing = nullptr;
    }
    const int alive = gl::live_object_count();
    std::cout << "\nGL objects alive after teardown: " << alive << (alive == 0 ? " (ok)" : " (LEAK)") << "\n";
    return alive == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "bench_render: " << e.what() << "\n";
        return 1;
    }
}
