// One image per effect: owns the uploaded scene and the programs of one GL
// context and wires the passes together. The context (and the Functions
// table, which gl objects point to) must outlive the Renderer and be
// current while it is used or destroyed.
#pragma once

#include "plan/camera.hpp"
#include "plan/curved_mirror.hpp"
#include "render/depth_policy.hpp"
#include "plan/effect.hpp"
#include "plan/effect_params.hpp"
#include "render/fog_pass.hpp"
#include "render/frame_window.hpp"
#include "render/gpu_scene.hpp"
#include "render/non_affine_pass.hpp"
#include "render/pass_context.hpp"
#include "render/programs.hpp"
#include "render/target_pool.hpp"
#include "plan/scene_fit.hpp"
#include "plan/link_moves.hpp"
#include "plan/view_links.hpp"
#include "plan/split_geometry.hpp"
#include "plan/world_geometry.hpp"

#include <frustum/result.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <gl/offscreen_target.hpp>
#include <image/image.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace render {

// The effect values (plan/effect_params.hpp, each default stated there
// once: tiles, mirror method, curved cap, lens grid and power, the fit, fog,
// recursion; the stereo rig and mirror placement are the caller's) and
// what a frame adds.
struct RenderOptions : plan::EffectParams {
    // Called as each pass of render_into() ends, with the pass's name
    // ("reflection" in the mirror effect, then "main view"; the portal and
    // recursion effects: "level k (n views)" after each view through k
    // links, deepest first, then "main view"); unset: not called (the
    // window's GPU timer and fragment counter mark their queries there).
    std::function<void(const char* pass)> pass_end;
    int width_px = 640;
    int height_px = 360;
    DepthPath depth = DepthPath::ClipControlWhenAvailable;
    glm::vec3 mirror_tint{0.92f, 0.95f, 1.0f};         // mirror and curved effects
    plan::NonAffineOptions nonaffine;                  // nonaffine effect: subdivision, culling (the slit
                                                       // and pivot come from `fit`, per frame)
    std::vector<plan::LinkMove> link_moves;            // recursion effect: each link moved after placement
    Lighting lighting;
    // MSAA samples of render()'s frame (gl::choose_samples()): kAutomaticSamples
    // = 4 or the context's maximum, 1 = off. render_into() uses the target's.
    int msaa_samples = gl::kAutomaticSamples;
};

class Renderer {
public:
    // Uploads the scene and builds the programs; copies what it needs of
    // `scene` (which may be destroyed afterwards).
    static frustum::Result<Renderer> create(const gl::Context& context, const gl::Functions& fn,
                                            const scene::Scene& scene);

    // Renders `effect` into a new width_px x height_px RGBA8 image (rows top
    // to bottom), multisampled with options.msaa_samples and resolved. The frustum effect shows cameras.main (and its mirror
    // reflection) from cameras.overview; the others use cameras.main. The
    // mirror effect of a scene without a mirror is the plain frame.
    frustum::Result<image::Image> render(plan::Effect effect, const plan::Cameras& cameras,
                                         const RenderOptions& options) const;

    // As render(), but into an existing target, which sets the size (the
    // effect is laid out for frame.width() x frame.height(); options.width_px
    // and height_px are not used, nor msaa_samples: the target's samples
    // are), and leaves it bound; a multisampled target is not resolved yet. A window renders
    // each frame this way and blits the target to its framebuffer.
    frustum::Status render_into(plan::Effect effect, const plan::Cameras& cameras, const RenderOptions& options,
                                const gl::OffscreenTarget& frame) const;

    // As render_into(), with `frame` holding window.rect of a
    // window.full_width_px x window.full_height_px frame (a poster tile,
    // poster.hpp): every effect is planned for the whole frame and the target
    // gets its crop (§5.1), the same pixels a direct render of the whole
    // frame has there. Errors: a window outside the frame or not the
    // target's size.
    // `cache`, when given, keeps what every tile of the frame draws the same
    // (frame_cache.hpp): pass one cache for all the tiles of one frame.
    frustum::Status render_into(plan::Effect effect, const plan::Cameras& cameras, const RenderOptions& options,
                                const gl::OffscreenTarget& frame, const FrameWindow& window,
                                FrameCache* cache = nullptr) const;

    // Moves the mirror for every later frame by `motion`, a rigid world
    // transform (rotation + translation) relative to where the scene put it;
    // the identity puts it back. Its rectangle, its surface instance and the
    // instances in `attached` (e.g. a backing board) move together, so every
    // effect sees the moved mirror. Errors: the scene has no mirror, an
    // index out of range, or a motion that is not rigid, e.g.
    // "render::Renderer::move_mirror(): motion must be rigid (det 1, orthonormal columns, last row 0 0 0 1), got det=8".
    frustum::Status move_mirror(const glm::mat4& motion, const std::vector<int>& attached);

    // The depth range render() hands the GPU for `path` on this context.
    frustum::DepthRange gpu_depth_range(DepthPath path) const;

    // The GL table the renderer draws with (render_poster() makes its tiles with it).
    const gl::Functions& functions() const { return *fn_; }

    // For tests that draw with the passes directly.
    const GpuScene& gpu_scene() const { return gpu_scene_; }
    const Programs& programs() const { return programs_; }
    PassContext pass_context(const DepthPolicy& depth, const Lighting& lighting) const;

private:
    // Portal and recursion effects: the links beside the model and their
    // quads on the GPU (view_links.hpp), one group per effect / LinkSet.
    struct LinkGroup {
        std::vector<plan::ViewLink> links;
        GpuScene quads;
    };

    Renderer(const gl::Context& context, const gl::Functions& fn, GpuScene gpu_scene, Programs programs,
             FogPass fog_pass, const scene::Scene& scene, std::vector<LinkGroup> link_groups);

    frustum::Status draw(plan::Effect effect, const PassContext& ctx, const gl::OffscreenTarget& frame,
                         const plan::Cameras& cameras, const RenderOptions& options) const;
    // draw()'s effects that plan more than one pass: each plans for the whole
    // frame (cameras.main.pair) and draws into `frame` its crop.
    frustum::Status draw_lens(const PassContext& ctx, const gl::OffscreenTarget& frame,
                              const frustum::MatrixPair<float>& camera, const RenderOptions& options) const;
    frustum::Status draw_non_affine(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                    const frustum::MatrixPair<float>& camera, const RenderOptions& options) const;
    frustum::Status draw_views(plan::Effect effect, const PassContext& ctx, const gl::OffscreenTarget& frame,
                               const frustum::MatrixPair<float>& camera, const RenderOptions& options,
                               const FrameWindow& window) const;
    frustum::Status draw_frustums(const PassContext& ctx, const plan::Cameras& cameras, const RenderOptions& options,
                                  const FrameWindow& window) const;

    const gl::Context* context_;
    const gl::Functions* fn_;
    GpuScene gpu_scene_;
    Programs programs_;
    FogPass fog_pass_;
    std::optional<scene::MirrorRect> mirror_;
    scene::Bounds bounds_;
    std::vector<scene::Bounds> boxes_; // instance_boxes(): where placed links look for what is in front
    // Where the scene put the mirror and the instances (move_mirror() starts
    // from these), and which instances it moved last.
    std::optional<scene::MirrorRect> scene_mirror_;
    std::vector<glm::mat4> scene_worlds_;
    std::vector<int> moved_instances_;
    std::optional<scene::LensSpot> lens_; // lens effect
    // [0] portal pair, [1] facing mirrors, [2] facing portal. Mutable: the
    // links follow each frame's camera (placed by link_group()).
    mutable std::vector<LinkGroup> link_groups_;
    // The recursion views' targets, kept from frame to frame (mutable like the links).
    mutable TargetPool recursion_targets_;
    frustum::Result<const LinkGroup*> link_group(plan::Effect effect, const RenderOptions& options,
                                                 const frustum::MatrixPair<float>& camera) const;
    // Nonaffine effect: the scene's triangles placed by gpu_scene_'s instances
    // and split, kept while they and the fitted edge length stay (mutable like the links).
    mutable plan::SplitGeometryCache nonaffine_geometry_;
};

} // namespace render
