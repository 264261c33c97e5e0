// Recursive mirrors (issue 16, docs/performance.md "Portals and recursive
// mirrors"): two facing mirrors beside the showcase's model
// (render::place_facing_links), depth 1..6, 1280x720, drawn
//   tight: each level cropped to its screen rectangle intersected with its
//          parent's, oblique near plane, culled with its culling pair;
//   full:  the same views over the whole viewport with the mirror plane as
//          a fragment clip plane and no culling (a Reflector chain, a
//          stencil portal renderer).
// Counters per frame: fragments (GL_FRAGMENT_SHADER_INVOCATIONS_ARB when the
// context has it, and samples written), views, primitives drawn and culled,
// culled per level. cpu/recursion_plan: plan_view_tree() alone (every pair,
// rectangle and culling pair of the frame).
#include "bench_render_setup.hpp"

#include <render/recursion_pass.hpp>
#include <plan/view_links.hpp>
#include <plan/view_tree.hpp>

#include <benchmark/benchmark.h>
#include <gl/offscreen_target.hpp>

#include <iostream>
#include <memory>
#include <string>

namespace {

using bench_render::kHeightPx;
using bench_render::kWidthPx;

std::vector<render::ViewLink> facing_mirrors() {
    auto links = render::place_facing_links(bench_render::main_camera(), bench_render::showcase().world_bounds,
                                            render::LinkSet::Mirrors);
    if (!links) {
        throw std::runtime_error(links.error());
    }
    return *links;
}

std::vector<render::ViewNode> plan(const std::vector<render::ViewLink>& links, int depth, render::ViewBounds bounds) {
    auto nodes = render::plan_view_tree(bench_render::main_camera(), links, {depth, kWidthPx, kHeightPx, bounds});
    if (!nodes) {
        throw std::runtime_error(nodes.error());
    }
    return *nodes;
}

struct Scene {
    std::unique_ptr<bench_render::Gpu> gpu;
    std::vector<render::ViewLink> links;
    std::optional<render::GpuScene> quads;
    std::optional<gl::OffscreenTarget> frame;
};

Scene& gpu_scene() {
    static Scene s = [] {
        Scene out;
        std::string why;
        // OSMesa first: a desktop GL context, which has GL_SAMPLES_PASSED.
        out.gpu = bench_render::make_gpu(gl::Backend::OsMesa, why);
        if (!out.gpu) {
            out.gpu = bench_render::make_gpu(gl::Backend::Egl, why);
        }
        if (!out.gpu) {
            throw std::runtime_error("no GL context: " + why);
        }
        out.links = facing_mirrors();
        auto quads = render::GpuScene::upload(*out.gpu->fn, render::link_scene(out.links));
        auto frame = gl::OffscreenTarget::create(*out.gpu->fn, {kWidthPx, kHeightPx});
        if (!quads || !frame) {
            throw std::runtime_error(!quads ? quads.error() : frame.error());
        }
        out.quads.emplace(std::move(*quads));
        out.frame.emplace(std::move(*frame));
        return out;
    }();
    return s;
}

void frame_case(benchmark::State& state, int depth, render::ViewBounds bounds) {
    Scene& s = gpu_scene();
    const auto nodes = plan(s.links, depth, bounds);
    const render::PassContext ctx = s.gpu->pass();
    const render::RecursionDraw draw{nodes, s.links, *s.quads, glm::vec3(1.0f)};
    render::RecursionStats stats;
    const auto draw_once = [&](render::RecursionStats* out) {
        if (auto status = render::draw_recursion_frame(ctx, *s.frame, draw, out); !status) {
            state.SkipWithError(status.error().c_str());
        }
    };
    draw_once(&stats);
    const bench_render::FragmentCounts fragments =
        bench_render::count_fragments(*s.gpu, [&](bool) { draw_once(nullptr); });
    for (auto _ : state) {
        draw_once(nullptr);
        s.gpu->fn->Finish();
    }
    state.counters["fs_invocations"] = static_cast<double>(fragments.fs_invocations);
    state.counters["samples_written"] = static_cast<double>(fragments.written);
    state.counters["views"] = static_cast<double>(nodes.size());
    long drawn = 0, culled = 0;
    for (std::size_t level = 0; level < stats.per_level.size(); ++level) {
        drawn += stats.per_level[level].drawn;
        culled += stats.per_level[level].culled;
        state.counters["culled_L" + std::to_string(level)] = static_cast<double>(stats.per_level[level].culled);
    }
    state.counters["drawn"] = static_cast<double>(drawn);
    state.counters["culled"] = static_cast<double>(culled);
}

void plan_case(benchmark::State& state, int depth) {
    const auto links = facing_mirrors();
    const auto camera = bench_render::main_camera();
    std::size_t views = 0;
    for (auto _ : state) {
        auto nodes = render::plan_view_tree(camera, links, {depth, kWidthPx, kHeightPx, render::ViewBounds::Tight});
        views = nodes ? nodes->size() : 0;
        benchmark::DoNotOptimize(nodes);
    }
    state.counters["views"] = static_cast<double>(views);
}

} // namespace

int main(int argc, char** argv) {
    for (int depth = 1; depth <= 6; ++depth) {
        const std::string d = std::to_string(depth);
        benchmark::RegisterBenchmark(("recursion/tight/depth:" + d).c_str(),
                                     [depth](benchmark::State& s) { frame_case(s, depth, render::ViewBounds::Tight); })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("recursion/full/depth:" + d).c_str(), [depth](benchmark::State& s) {
            frame_case(s, depth, render::ViewBounds::FullViewport);
        })->Unit(benchmark::kMillisecond)->UseRealTime();
        benchmark::RegisterBenchmark(("cpu/recursion_plan/depth:" + d).c_str(),
                                     [depth](benchmark::State& s) { plan_case(s, depth); })
            ->Unit(benchmark::kMicrosecond);
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
