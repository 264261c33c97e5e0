// Shared by bench_render*.cpp: the showcase scene, a GL context with a
// renderer, the camera placements of the mirror comparison, the lens of the
// lens tiles, and fragment counting with queries.
#pragma once

#include <frustum/crop.hpp>
#include <frustum/lens.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/plane.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <plan/camera.hpp>
#include <render/depth_policy.hpp>
#include <render/lens_pass.hpp>
#include <plan/mirror_geometry.hpp>
#include <render/pass_context.hpp>
#include <render/renderer.hpp>
#include <scene/scene.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bench_render {

inline constexpr int kWidthPx = 1280;
inline constexpr int kHeightPx = 720;

// assets/showcase.gltf, loaded once; throws std::runtime_error when missing.
const scene::Scene& showcase();

// The showcase's "main" camera at kWidthPx x kHeightPx.
frustum::MatrixPair<float> main_camera();

// The main camera's lens (yfov, aspect, near, far) looking at the mirror's
// centre from `distance_m` along the main eye's direction from that centre.
frustum::MatrixPair<float> camera_at_distance(float distance_m);

// One mirror size of the reflection comparison: the camera moved along the
// main eye's line so that the mirror's screen rectangle covers `fraction`
// of the 1280x720 frame (1 = the rectangle is the whole frame).
struct MirrorCase {
    std::string label;      // "1/16", "1/4", "1/1"
    double target_fraction; // 1/16, 1/4, 1
    float distance_m;
    frustum::MatrixPair<float> camera;
    plan::PixelRect rect;      // the mirror's screen rectangle
    double coverage;           // rect area / frame area
    frustum::Plane<float> plane; // the mirror plane (positive on the reflecting side)
};
MirrorCase make_mirror_case(const std::string& label, double fraction);

// The renderer's lens effect on the main camera, as Renderer draws it:
// render::lens_on_near_plane() of the showcase's lens spot, power 2, the
// lens disc not drawn; `grid` x `grid` tiles.
render::LensDraw lens_draw(int grid);

// A context of one backend, its entry points and a renderer of the showcase.
// Members die in reverse order: renderer, table, context.
struct Gpu {
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<gl::Functions> fn;
    std::optional<render::Renderer> renderer;
    std::optional<render::DepthPolicy> depth;

    render::PassContext pass() const { return renderer->pass_context(*depth, render::Lighting{}); }
};
// Null with `why` set when the backend cannot make a context.
std::unique_ptr<Gpu> make_gpu(gl::Backend backend, std::string& why);

// What one draw costs in fragments, from queries on a desktop GL context
// (GL_SAMPLES_PASSED counts samples, unlike GLES's boolean
// GL_ANY_SAMPLES_PASSED):
// - rasterized: fragments produced by rasterization, overdraw included:
//   GL_SAMPLES_PASSED with the depth test set to GL_ALWAYS, no depth writes
//   and the scene program without discard. A discarding shader runs on all
//   of them.
// - written: GL_SAMPLES_PASSED with the real state and program (passed the
//   depth test and not discarded).
// - fs_invocations: GL_FRAGMENT_SHADER_INVOCATIONS_ARB with the real state
//   and program, when the context has ARB_pipeline_statistics_query (llvmpipe
//   counts whole 4x4 blocks: 16 per block it shades); -1 otherwise.
struct FragmentCounts {
    std::int64_t rasterized = -1, written = -1, fs_invocations = -1;
};
// `draw(count_all)` draws once: count_all = true asks for the plain program
// (no clip plane) with depth func GL_ALWAYS and depth writes off, set by the
// callee after its begin_frame(); false for the real pass.
FragmentCounts count_fragments(const Gpu& gpu, const std::function<void(bool count_all)>& draw);

} // namespace bench_render
