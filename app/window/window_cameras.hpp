// The scene's cameras as the window needs them at its framebuffer size.
#pragma once

#include <frustum/result.hpp>
#include <render/camera.hpp>
#include <scene/scene.hpp>

namespace window {

// render::make_cameras() for a width_px x height_px framebuffer, except
// that a glTF camera's own aspect ratio gives way to the framebuffer's when
// the two differ by more than 0.1% (the picture would be stretched after a
// resize); this applies to the main camera and to a scene camera named
// "overview". At a size of the camera's own aspect the pairs are exactly
// make_cameras()'s, so the window matches `frustum-demo render`.
frustum::Result<render::Cameras> window_cameras(const scene::Scene& scene, int main_camera, int width_px,
                                                int height_px);

} // namespace window
