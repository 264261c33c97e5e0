// One image per effect: owns the uploaded scene and the programs of one GL
// context and wires the passes together. The context (and the Functions
// table, which gl objects point to) must outlive the Renderer and be
// current while it is used or destroyed.
#pragma once

#include "render/camera.hpp"
#include "render/depth_policy.hpp"
#include "render/effect.hpp"
#include "render/gpu_scene.hpp"
#include "render/pass_context.hpp"
#include "render/programs.hpp"

#include <frustum/result.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <gl/offscreen_target.hpp>
#include <image/image.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace render {

struct RenderOptions {
    int width_px = 640;
    int height_px = 360;
    DepthPath depth = DepthPath::ClipControlWhenAvailable;
    MirrorMethod mirror_method = MirrorMethod::Oblique; // mirror and frustum effects
    int tile_columns = 3;                              // tiles effect
    int tile_rows = 2;
    glm::vec3 mirror_tint{0.92f, 0.95f, 1.0f};
    Lighting lighting;
};

class Renderer {
public:
    // Uploads the scene and builds the programs; copies what it needs of
    // `scene` (which may be destroyed afterwards).
    static frustum::Result<Renderer> create(const gl::Context& context, const gl::Functions& fn,
                                            const scene::Scene& scene);

    // Renders `effect` into a new width_px x height_px RGBA8 image (rows top
    // to bottom). The frustum effect shows cameras.main (and its mirror
    // reflection) from cameras.overview; the others use cameras.main. The
    // mirror effect of a scene without a mirror is the plain frame.
    frustum::Result<image::Image> render(Effect effect, const Cameras& cameras, const RenderOptions& options) const;

    // The depth range render() hands the GPU for `path` on this context.
    frustum::DepthRange gpu_depth_range(DepthPath path) const;

    // For tests that draw with the passes directly.
    const GpuScene& gpu_scene() const { return gpu_scene_; }
    const Programs& programs() const { return programs_; }
    PassContext pass_context(const DepthPolicy& depth, const Lighting& lighting) const;

private:
    Renderer(const gl::Context& context, const gl::Functions& fn, GpuScene gpu_scene, Programs programs,
             const scene::Scene& scene);

    frustum::Status draw(Effect effect, const PassContext& ctx, const gl::OffscreenTarget& frame,
                         const Cameras& cameras, const RenderOptions& options) const;

    const gl::Context* context_;
    const gl::Functions* fn_;
    GpuScene gpu_scene_;
    Programs programs_;
    std::optional<scene::MirrorRect> mirror_;
    scene::Bounds bounds_;
};

} // namespace render
