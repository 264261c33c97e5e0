// The browser's WebGL 2 context (= OpenGL ES 3.0) on an HTML canvas, for
// emscripten builds (app/web). It stands where EGL or OSMesa stand on the
// desktop: gl::Functions::load() fills the same table through
// get_proc_address(), here from emscripten's WebGL 2 implementation of the
// GLES 3 functions, so the renderer, its shaders and the frustum library are
// the desktop's unchanged.
//
// The canvas is framebuffer 0 (no depth, stencil or multisampling: the
// renderer draws into its own framebuffer objects and blits the frame, as
// the desktop window does, gl/window_framebuffer.hpp). Extensions: WebGL 2
// exposes neither clip control nor KHR_debug, so Functions::ClipControl and
// DebugMessageCallback stay null and depth takes the [-1, 1] path.
#pragma once

#include "gl/context.hpp"

#include <frustum/result.hpp>

#include <memory>
#include <string>

namespace gl {

class WebGlContext final : public Context {
public:
    // A WebGL 2 context on the canvas that the CSS selector `canvas` names
    // (e.g. "#canvas"), current on return. Errors name the selector, e.g.
    // "gl::WebGlContext::create(): no WebGL 2 context on '#canvas' (emscripten error -4)".
    // options.debug is refused (WebGL has no KHR_debug).
    static frustum::Result<std::unique_ptr<WebGlContext>> create(const std::string& canvas,
                                                                 const ContextOptions& options);
    ~WebGlContext() override;

    frustum::Status make_current() override;
    // The GLES 3.0 functions gl::Functions requires, by name; null for any other.
    Proc get_proc_address(const char* name) const override;
    Backend backend() const override { return Backend::Web; }

    const std::string& canvas() const { return canvas_; }

private:
    WebGlContext(const ContextOptions& options, std::string canvas, int handle)
        : Context(options), canvas_(std::move(canvas)), handle_(handle) {}

    std::string canvas_;
    int handle_ = 0; // EMSCRIPTEN_WEBGL_CONTEXT_HANDLE
};

} // namespace gl
