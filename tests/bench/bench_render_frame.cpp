// The CPU per frame of every effect (issue 34, last item): the planning the
// renderer does on the CPU for one frame, without GL, on the showcase at
// 640x360, each effect at its defaults (plan::resolve_effects() of
// EffectParams{}) and at its largest documented grid. Every case calls the
// plan functions render::Renderer::draw() and its passes call per frame
// (app/render/renderer.cpp, *_pass.cpp), in the same order, and keeps what
// they return (no GL calls, no uploads).
//   bench_render --cpu_frame_table   (no GL context; prints the table)
#include "bench_render_cpu.hpp"

#include "bench_render_setup.hpp"

#include <frustum/crop.hpp>
#include <frustum/lens.hpp>
#include <frustum/queries.hpp>
#include <plan/camera.hpp>
#include <plan/curved_mirror.hpp>
#include <plan/effect_params.hpp>
#include <plan/frustum_lines.hpp>
#include <plan/link_moves.hpp>
#include <plan/mirror_geometry.hpp>
#include <plan/non_affine_frustum.hpp>
#include <plan/scene_fit.hpp>
#include <plan/stereo.hpp>
#include <plan/view_links.hpp>
#include <plan/view_tree.hpp>
#include <plan/split_geometry.hpp>
#include <plan/world_geometry.hpp>
#include <render/curved_pass.hpp>
#include <render/non_affine_pass.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench_render {
namespace {

constexpr int kW = 640, kH = 360;

template <class T>
T must(frustum::Result<T> r, const char* what) {
    if (!r) {
        throw std::runtime_error(std::string("cpu/frame: ") + what + ": " + r.error());
    }
    return std::move(*r);
}

struct FrameSetup {
    scene::Scene scene;
    plan::EffectParams params; // resolved for kW x kH
    int main_index = 0;
    plan::WorldGeometry object_geometry;
};

const FrameSetup& setup() {
    static const FrameSetup s = [] {
        FrameSetup out{showcase(), {}, 0, plan::WorldGeometry::in_object_space(showcase())};
        const plan::ResolvedEffects resolved = plan::resolve_effects(plan::EffectParams{}, out.scene);
        if (resolved.refused) {
            throw std::runtime_error("cpu/frame: " + *resolved.refused);
        }
        out.params = resolved.params;
        out.main_index = must(plan::find_camera(out.scene, std::nullopt), "find_camera");
        out.object_geometry = plan::WorldGeometry::in_object_space(out.scene);
        return out;
    }();
    return s;
}

// The camera pairs of a frame (main, overview): every row starts with them.
plan::Cameras cameras(const FrameSetup& s) { return must(plan::make_cameras(s.scene, s.main_index, kW, kH), "cameras"); }

plan::FrustumLineStyle line_style(const scene::Bounds& bounds) { // renderer.cpp's
    const float diagonal_m = glm::length(bounds.max - bounds.min);
    const float size_m = diagonal_m > 0.0f ? diagonal_m : 1.0f;
    return {0.02f * size_m, 2.0f * size_m};
}

using Frame = std::function<void(const FrameSetup&, benchmark::State&)>;

void plain(const FrameSetup& s, benchmark::State&) {
    auto c = cameras(s);
    benchmark::DoNotOptimize(c);
}

void mirror(const FrameSetup& s, benchmark::State&) {
    const auto c = cameras(s);
    auto plan = must(plan::plan_reflection(*s.scene.mirror, c.main.pair, kW, kH, s.params.mirror_method,
                                           s.scene.world_bounds),
                     "plan_reflection");
    benchmark::DoNotOptimize(plan);
}

Frame tiles(int columns, int rows) {
    return [columns, rows](const FrameSetup& s, benchmark::State&) {
        const auto c = cameras(s);
        auto t = must(frustum::crop_tiles(c.main.pair, kW, kH, columns, rows), "crop_tiles");
        benchmark::DoNotOptimize(t);
    };
}

void frustum_view(const FrameSetup& s, benchmark::State&) {
    const auto c = cameras(s);
    const auto style = line_style(s.scene.world_bounds);
    auto main_lines = plan::frustum_lines(c.main.pair, style);
    auto reflection = must(plan::plan_reflection(*s.scene.mirror, c.main.pair, kW, kH, s.params.mirror_method,
                                                 s.scene.world_bounds),
                           "plan_reflection");
    if (reflection) {
        auto lines = plan::frustum_lines(reflection->pair, style);
        benchmark::DoNotOptimize(lines);
    }
    benchmark::DoNotOptimize(main_lines);
}

Frame curved(int patches) {
    return [patches](const FrameSetup& s, benchmark::State&) {
        const auto c = cameras(s);
        const auto cap = must(plan::CurvedMirror::create(*s.scene.mirror, s.params.curved.shape,
                                                         s.params.curved.sagitta_m),
                              "CurvedMirror::create");
        const auto eye = frustum::eye_point(c.main.pair);
        auto plan = must(plan::plan_curved_mirror(cap, glm::dvec3(*eye), s.scene.world_bounds, patches),
                         "plan_curved_mirror");
        auto tile = render::curved_tile_size(cap, c.main.pair, patches, kW, kH);
        benchmark::DoNotOptimize(plan);
        benchmark::DoNotOptimize(tile);
    };
}

Frame lens(int grid) {
    return [grid](const FrameSetup& s, benchmark::State&) {
        const auto c = cameras(s);
        const auto l = must(plan::fit_lens(c.main.pair, s.scene.lens, s.scene.world_bounds, s.params.fit,
                                           s.params.lens_power),
                            "fit_lens");
        auto t = must(frustum::lens_tiles(c.main.pair, l, kW, kH, grid, grid), "lens_tiles");
        benchmark::DoNotOptimize(t);
    };
}

// Renderer::draw()'s non-affine case and draw_non_affine_frame()'s CPU part:
// the fit, the six planes, the scene's split triangles from the renderer's
// cache (placed and split once: the instances do not move between frames),
// every vertex tested against the denominators and the index list built
// (batch_non_affine(); no upload).
void nonaffine(const FrameSetup& s, benchmark::State& state) {
    static plan::SplitGeometryCache cache(s.object_geometry);
    const auto c = cameras(s);
    const plan::NonAffineOptions base; // RenderOptions::nonaffine's default
    const auto fitted = must(plan::fit_non_affine(c.main.pair, s.scene.world_bounds, base, s.params.fit),
                             "fit_non_affine");
    const auto slits = must(plan::crossed_slits_frustum(c.main.pair, fitted, frustum::DepthRange::ZeroToOne),
                            "crossed_slits_frustum");
    const plan::SplitGeometry& split = cache.get(s.scene.instances, fitted.max_edge_m);
    const render::NonAffineBatch batch = render::batch_non_affine(split, slits, fitted);
    benchmark::DoNotOptimize(batch.indices.data());
    state.counters["triangles"] = static_cast<double>(batch.stats.triangles);
}

// The same frame after an instance moved (or the first frame): the scene
// placed, split and gathered again before the batch.
void nonaffine_rebuilt(const FrameSetup& s, benchmark::State& state) {
    const auto c = cameras(s);
    const auto fitted = must(plan::fit_non_affine(c.main.pair, s.scene.world_bounds, plan::NonAffineOptions{},
                                                  s.params.fit),
                             "fit_non_affine");
    const auto slits = must(plan::crossed_slits_frustum(c.main.pair, fitted, frustum::DepthRange::ZeroToOne),
                            "crossed_slits_frustum");
    const plan::SplitGeometry split =
        plan::SplitGeometry::build(s.object_geometry.placed(s.scene.instances), fitted.max_edge_m);
    const render::NonAffineBatch batch = render::batch_non_affine(split, slits, fitted);
    benchmark::DoNotOptimize(batch.indices.data());
    state.counters["triangles"] = static_cast<double>(batch.stats.triangles);
}

// The non-affine row without the geometry: cameras, fit and the six planes.
void nonaffine_planes(const FrameSetup& s, benchmark::State&) {
    const auto c = cameras(s);
    const auto fitted = must(plan::fit_non_affine(c.main.pair, s.scene.world_bounds, plan::NonAffineOptions{},
                                                  s.params.fit),
                             "fit_non_affine");
    auto slits = must(plan::crossed_slits_frustum(c.main.pair, fitted, frustum::DepthRange::ZeroToOne),
                      "crossed_slits_frustum");
    benchmark::DoNotOptimize(slits);
}

// Renderer::link_group() and plan_view_tree(): the links placed for this
// frame's camera, their quads' world matrices, the tree of views.
Frame links(bool portal, int depth) {
    return [portal, depth](const FrameSetup& s, benchmark::State& state) {
        const auto c = cameras(s);
        auto placed = must(portal ? plan::place_portal_pair(c.main.pair, s.scene.world_bounds)
                                  : plan::place_facing_links(c.main.pair, s.scene.world_bounds,
                                                             s.params.recursion_links),
                           "place links");
        if (!portal) {
            plan::move_links(placed, {});
        }
        glm::mat4 worlds[3];
        for (const plan::ViewLink& link : placed) {
            worlds[0] = plan::link_world(link, false);
            if (link.kind == plan::ViewLink::Kind::Portal) {
                worlds[1] = plan::link_world(link, true);
                worlds[2] = plan::entry_frame_world(link);
            }
            benchmark::DoNotOptimize(worlds);
        }
        auto nodes = must(plan::plan_view_tree(c.main.pair, placed,
                                               plan::ViewTreeRequest{depth, kW, kH, plan::ViewBounds::Tight}),
                          "plan_view_tree");
        state.counters["views"] = static_cast<double>(nodes.size());
        benchmark::DoNotOptimize(nodes);
    };
}

// run_render's stereo part: the rig (convergence derived from the scene)
// and both eyes' camera pairs. Each eye then plans its effect at 320x360.
void stereo(const FrameSetup& s, benchmark::State&) {
    const auto c = cameras(s);
    plan::EffectParams p = s.params;
    p.stereo = true;
    const auto rig = plan::stereo_rig(p, c.main.pair, s.scene);
    auto eyes = must(plan::stereo_cameras(c, *rig), "stereo_cameras");
    benchmark::DoNotOptimize(eyes);
}

struct Row {
    std::string name; // cpu/frame/<effect>/<grid>
    Frame frame;
};

std::vector<Row> rows() {
    const plan::EffectParams& d = setup().params;
    const int lens_max = std::min(128, std::min(kW, kH)); // --lens-grid 1..128, at most one tile per pixel
    const auto grid = [](int c, int r) { return std::to_string(c) + "x" + std::to_string(r); };
    return {
        {"cpu/frame/plain/default", plain},
        {"cpu/frame/mirror/default", mirror},
        {"cpu/frame/tiles/default_" + grid(d.tile_columns, d.tile_rows), tiles(d.tile_columns, d.tile_rows)},
        {"cpu/frame/tiles/32x32", tiles(32, 32)},
        {"cpu/frame/tiles/max_" + grid(kW, kH), tiles(kW, kH)}, // --tiles: at most one tile per pixel
        {"cpu/frame/frustum/default", frustum_view},
        {"cpu/frame/curved/default_" + grid(d.curved.patches, d.curved.patches), curved(d.curved.patches)},
        {"cpu/frame/curved/max_" + grid(plan::kMaxCurvedPatches, plan::kMaxCurvedPatches),
         curved(plan::kMaxCurvedPatches)},
        {"cpu/frame/lens/default_" + grid(d.lens_grid, d.lens_grid), lens(d.lens_grid)},
        {"cpu/frame/lens/max_" + grid(lens_max, lens_max), lens(lens_max)},
        {"cpu/frame/nonaffine/default", nonaffine},
        {"cpu/frame/nonaffine/planes_only", nonaffine_planes}, // a breakdown of the row above
        {"cpu/frame/nonaffine/rebuilt", nonaffine_rebuilt},    // an instance moved: the cache rebuilt
        {"cpu/frame/portal/default", links(true, 1)},
        {"cpu/frame/recursion/default_depth" + std::to_string(d.recursion_depth), links(false, d.recursion_depth)},
        {"cpu/frame/recursion/max_depth" + std::to_string(plan::kMaxRecursionDepth),
         links(false, plan::kMaxRecursionDepth)},
        {"cpu/frame/stereo/default", stereo},
    };
}

// Keeps the medians (and their spread) for the table after the run.
class TableReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> median_ns, cv;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            const std::string name = r.run_name.function_name;
            if (r.aggregate_name == "median") {
                median_ns[name] = r.GetAdjustedCPUTime();
            } else if (r.aggregate_name == "cv") {
                cv[name] = r.cpu_accumulated_time; // a fraction
            }
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

} // namespace

void register_cpu_frame_benchmarks() {
    for (const Row& row : rows()) {
        benchmark::RegisterBenchmark(row.name.c_str(),
                                     [frame = row.frame](benchmark::State& state) {
                                         const FrameSetup& s = setup();
                                         for (auto _ : state) {
                                             frame(s, state);
                                         }
                                     })
            ->Unit(benchmark::kNanosecond);
    }
}

// bench_render --dump_frame_scene: the showcase's fields the plan functions
// read (cameras, mirror, lens, bounds) and the resolved defaults, as C++ for
// count_frame_driver.cpp (which cannot load glTF under qemu).
int dump_frame_scene() {
    const FrameSetup& s = setup();
    const auto v3 = [](const glm::vec3& v) {
        char b[128];
        std::snprintf(b, sizeof b, "{%#.9gf, %#.9gf, %#.9gf}", v.x, v.y, v.z);
        return std::string(b);
    };
    std::printf("// Generated by `bench_render --dump_frame_scene` (tests/bench/bench_render_frame.cpp):\n"
                "// the showcase as the plan functions read it, and the defaults resolved at %dx%d.\n"
                "#pragma once\n#include <scene/scene.hpp>\n\nnamespace count_frame {\n"
                "inline constexpr int kWidthPx = %d, kHeightPx = %d, kMainCamera = %d;\n"
                "inline constexpr int kTileColumns = %d, kTileRows = %d, kPatches = %d, kLensGrid = %d, kDepth = %d;\n"
                "inline constexpr float kSagittaM = %#.9gf, kLensPower = %#.9gf;\n"
                "inline scene::Scene make_scene() {\n    scene::Scene s;\n",
                kW, kH, kW, kH, s.main_index, s.params.tile_columns, s.params.tile_rows, s.params.curved.patches,
                s.params.lens_grid, s.params.recursion_depth, s.params.curved.sagitta_m, s.params.lens_power);
    for (const scene::Camera& c : s.scene.cameras) {
        std::printf("    {\n        scene::Camera c;\n        c.name = \"%s\";\n        c.node_name = \"%s\";\n"
                    "        c.kind = scene::Camera::Kind::%s;\n",
                    c.name.c_str(), c.node_name.c_str(),
                    c.kind == scene::Camera::Kind::Perspective ? "Perspective" : "Orthographic");
        for (int col = 0; col < 4; ++col) {
            const glm::vec4 k = c.camera_to_world[col];
            std::printf("        c.camera_to_world[%d] = {%#.9gf, %#.9gf, %#.9gf, %#.9gf};\n", col, k.x, k.y, k.z, k.w);
        }
        std::printf("        c.yfov_rad = %#.9gf;\n        c.xmag = %#.9gf;\n        c.ymag = %#.9gf;\n"
                    "        c.znear_m = %#.9gf;\n",
                    c.yfov_rad, c.xmag, c.ymag, c.znear_m);
        if (c.aspect) std::printf("        c.aspect = %#.9gf;\n", *c.aspect);
        if (c.zfar_m) std::printf("        c.zfar_m = %#.9gf;\n", *c.zfar_m);
        std::printf("        s.cameras.push_back(c);\n    }\n");
    }
    if (s.scene.mirror) {
        const auto& m = *s.scene.mirror;
        std::printf("    s.mirror = scene::MirrorRect{%s, %s, %s, %d};\n", v3(m.corner).c_str(), v3(m.a1).c_str(),
                    v3(m.a2).c_str(), m.instance);
    }
    if (s.scene.lens) {
        std::printf("    s.lens = scene::LensSpot{%s, %#.9gf, %d};\n", v3(s.scene.lens->center).c_str(),
                    s.scene.lens->radius_m, s.scene.lens->instance);
    }
    std::printf("    s.world_bounds = scene::Bounds{%s, %s};\n    return s;\n}\n} // namespace count_frame\n",
                v3(s.scene.world_bounds.min).c_str(), v3(s.scene.world_bounds.max).c_str());
    return 0;
}

int run_cpu_frame_table(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--dump_frame_scene") {
            return dump_frame_scene();
        }
    }
    std::vector<char*> args{argv[0]};
    static char defaults[][64] = {"--benchmark_repetitions=9", "--benchmark_min_time=0.05",
                                  "--benchmark_enable_random_interleaving=true",
                                  "--benchmark_report_aggregates_only=true"};
    for (auto& d : defaults) {
        args.push_back(d);
    }
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) != "--cpu_frame_table") {
            args.push_back(argv[i]);
        }
    }
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data())) {
        return 2;
    }
    register_cpu_frame_benchmarks();
    TableReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    std::printf("\n| effect / grid (showcase, %dx%d) | CPU per frame, ns (median) | cv | under 0.2 ms |\n", kW, kH);
    std::printf("|---|---:|---:|---|\n");
    for (const Row& row : rows()) {
        const std::string& name = row.name;
        if (!reporter.median_ns.count(name)) {
            continue; // filtered out
        }
        const double ns = reporter.median_ns[name];
        std::printf("| %s | %.0f | %.1f%% | %s |\n", name.c_str() + 10, ns, 100.0 * reporter.cv[name],
                    ns < 200000.0 ? "yes" : "no");
    }
    return 0;
}

} // namespace bench_render
