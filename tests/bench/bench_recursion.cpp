// Recursive mirrors (issue 16, docs/performance.md "Portals and recursive
// mirrors"), 1280x720, depth 0..6, two layouts:
//   beside: the recursion effect's two facing mirrors beside the showcase's
//           model (plan::place_facing_links), the showcase's camera;
//   room:   two facing mirrors on the side walls of a closed room, the
//           camera looking into one (bench_recursion_room.hpp).
// Each drawn two ways:
//   tight: each level cropped to its screen rectangle intersected with its
//          parent's, oblique near plane, culled with its culling pair;
//   full:  the same views over the whole viewport with the mirror plane as
//          a fragment clip plane and no culling (a Reflector chain, a
//          stencil portal renderer).
// Depth 0 is the camera's own view alone (the mirrors drawn plain; culled
// in tight, not in full): the fragments of the levels >= 1 are a row's
// minus depth 0's.
// Counters per frame: fragments (GL_FRAGMENT_SHADER_INVOCATIONS_ARB when the
// context has it, and samples written), views, primitives drawn and culled,
// culled per level. cpu/<layout>/recursion_plan: plan_view_tree() alone
// (every pair, rectangle and culling pair of the frame). target/...: the
// cost of a full-viewport view's texture, created per frame or kept;
// .../kept_targets: the frame with its views' targets kept (TargetPool).
#include "bench_recursion_room.hpp"
#include "bench_render_setup.hpp"

#include <render/recursion_pass.hpp>
#include <plan/view_links.hpp>
#include <plan/view_tree.hpp>

#include <benchmark/benchmark.h>
#include <gl/offscreen_target.hpp>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace {

using bench_render::kHeightPx;
using bench_render::kWidthPx;

// One layout: its camera and links (CPU only).
struct Layout {
    frustum::MatrixPair<float> camera;
    std::vector<plan::ViewLink> links;
    const scene::Scene* scene; // what the layout's renderer draws
};

const Layout& layout(const std::string& name) {
    static const std::map<std::string, Layout> layouts = [] {
        std::map<std::string, Layout> out;
        const auto camera = bench_render::main_camera();
        auto links = plan::place_facing_links(camera, bench_render::showcase().world_bounds, plan::LinkSet::Mirrors);
        if (!links) {
            throw std::runtime_error(links.error());
        }
        out.emplace("beside", Layout{camera, *links, &bench_render::showcase()});
        static const bench_recursion::Room room = bench_recursion::make_room(kWidthPx, kHeightPx);
        out.emplace("room", Layout{room.camera, room.links, &room.scene});
        return out;
    }();
    return layouts.at(name);
}

std::vector<plan::ViewNode> view_tree(const Layout& l, int depth, plan::ViewBounds bounds) {
    auto nodes = plan::plan_view_tree(l.camera, l.links, {depth, kWidthPx, kHeightPx, bounds});
    if (!nodes) {
        throw std::runtime_error(nodes.error());
    }
    return *nodes;
}

// The GL side: one context, a renderer per layout's scene.
struct Gpu {
    std::unique_ptr<bench_render::Gpu> gpu;
    std::optional<gl::OffscreenTarget> frame;
    struct Drawn {
        std::vector<plan::ViewLink> links;   // the layout's, with their instances in `quads`
        std::optional<render::Renderer> own; // the room's renderer (beside uses gpu's)
        std::optional<render::GpuScene> quads;
    };
    std::map<std::string, Drawn> drawn;
};

Gpu& gpu() {
    static Gpu s = [] {
        Gpu out;
        std::string why;
        // OSMesa first: a desktop GL context, which has GL_SAMPLES_PASSED.
        out.gpu = bench_render::make_gpu(gl::Backend::OsMesa, why);
        if (!out.gpu) {
            out.gpu = bench_render::make_gpu(gl::Backend::Egl, why);
        }
        if (!out.gpu) {
            throw std::runtime_error("no GL context: " + why);
        }
        auto frame = gl::OffscreenTarget::create(*out.gpu->fn, {kWidthPx, kHeightPx});
        if (!frame) {
            throw std::runtime_error(frame.error());
        }
        out.frame.emplace(std::move(*frame));
        for (const char* name : {"beside", "room"}) {
            Gpu::Drawn d;
            d.links = layout(name).links;
            auto quads = render::GpuScene::upload(*out.gpu->fn, plan::link_scene(d.links));
            if (!quads) {
                throw std::runtime_error(quads.error());
            }
            d.quads.emplace(std::move(*quads));
            if (std::string(name) == "room") {
                auto own = render::Renderer::create(*out.gpu->context, *out.gpu->fn, *layout(name).scene);
                if (!own) {
                    throw std::runtime_error(own.error());
                }
                d.own.emplace(std::move(*own));
            }
            out.drawn.emplace(name, std::move(d));
        }
        return out;
    }();
    return s;
}

// kept_targets: the views' targets from a render::TargetPool kept across
// the frames (the renderer's way), else made and freed per view.
void frame_case(benchmark::State& state, const std::string& name, int depth, plan::ViewBounds bounds,
                bool kept_targets = false) {
    Gpu& s = gpu();
    const Gpu::Drawn& d = s.drawn.at(name);
    const auto nodes = view_tree(layout(name), depth, bounds);
    const render::PassContext ctx = d.own ? d.own->pass_context(*s.gpu->depth, render::Lighting{}) : s.gpu->pass();
    render::TargetPool pool;
    const render::RecursionDraw draw{nodes, d.links, *d.quads, glm::vec3(1.0f), kept_targets ? &pool : nullptr};
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
    double rect_px = 0.0; // the views' rectangles, level 0 included
    for (const plan::ViewNode& node : nodes) {
        rect_px += static_cast<double>(node.rect.width) * node.rect.height;
    }
    state.counters["viewport_px"] = rect_px;
    long drawn = 0, culled = 0;
    for (std::size_t level = 0; level < stats.per_level.size(); ++level) {
        drawn += stats.per_level[level].drawn;
        culled += stats.per_level[level].culled;
        state.counters["culled_L" + std::to_string(level)] = static_cast<double>(stats.per_level[level].culled);
    }
    state.counters["drawn"] = static_cast<double>(drawn);
    state.counters["culled"] = static_cast<double>(culled);
}

void plan_case(benchmark::State& state, const std::string& name, int depth) {
    const Layout& l = layout(name);
    std::size_t views = 0;
    for (auto _ : state) {
        auto nodes = plan::plan_view_tree(l.camera, l.links, {depth, kWidthPx, kHeightPx, plan::ViewBounds::Tight});
        views = nodes ? nodes->size() : 0;
        benchmark::DoNotOptimize(nodes);
    }
    state.counters["views"] = static_cast<double>(views);
}

// What a view's own texture costs: a full-viewport target (colour texture +
// depth, as draw_recursion_frame() makes per view and frame) created,
// cleared and resolved, against clearing one that already exists (what a
// renderer that keeps its targets pays).
void target_case(benchmark::State& state, bool create) {
    Gpu& s = gpu();
    const render::PassContext ctx = s.gpu->pass();
    const gl::OffscreenTargetOptions options{kWidthPx, kHeightPx, gl::ColorStorage::Texture, gl::DepthFormat::Depth24,
                                             ctx.samples};
    auto kept = gl::OffscreenTarget::create(*s.gpu->fn, options);
    if (!kept) {
        state.SkipWithError(kept.error().c_str());
        return;
    }
    for (auto _ : state) {
        if (create) {
            auto target = gl::OffscreenTarget::create(*s.gpu->fn, options);
            if (!target) {
                state.SkipWithError(target.error().c_str());
                return;
            }
            render::begin_frame(ctx);
            target->resolve();
            s.gpu->fn->Finish();
        } else {
            kept->bind();
            render::begin_frame(ctx);
            kept->resolve();
            s.gpu->fn->Finish();
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    benchmark::RegisterBenchmark("target/full_viewport/create_clear", [](benchmark::State& s) { target_case(s, true); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark("target/full_viewport/clear_only", [](benchmark::State& s) { target_case(s, false); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    for (const std::string name : {"beside", "room"}) {
        for (int depth = 0; depth <= 6; ++depth) {
            const std::string d = std::to_string(depth);
            benchmark::RegisterBenchmark(("recursion/" + name + "/tight/depth:" + d).c_str(),
                                         [name, depth](benchmark::State& s) {
                                             frame_case(s, name, depth, plan::ViewBounds::Tight);
                                         })
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
            // Depth 0: the camera's view alone, culled (tight) or not (full).
            benchmark::RegisterBenchmark(("recursion/" + name + "/full/depth:" + d).c_str(),
                                         [name, depth](benchmark::State& s) {
                                             frame_case(s, name, depth, plan::ViewBounds::FullViewport);
                                         })
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
            if (depth == 2 || depth == 4) {
                for (const auto& [bounds, label] : {std::pair{plan::ViewBounds::Tight, "tight"},
                                                    std::pair{plan::ViewBounds::FullViewport, "full"}}) {
                    benchmark::RegisterBenchmark(
                        ("recursion/" + name + "/" + label + "/depth:" + d + "/kept_targets").c_str(),
                        [name, depth, bounds = bounds](benchmark::State& s) { frame_case(s, name, depth, bounds, true); })
                        ->Unit(benchmark::kMillisecond)
                        ->UseRealTime();
                }
            }
            if (depth == 0) {
                continue;
            }
            benchmark::RegisterBenchmark(("cpu/" + name + "/recursion_plan/depth:" + d).c_str(),
                                         [name, depth](benchmark::State& s) { plan_case(s, name, depth); })
                ->Unit(benchmark::kMicrosecond);
        }
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
