// OpenGL ES 3.x through EGL on Mesa's surfaceless platform: no window system,
// no surface, rendering only into framebuffer objects.
#pragma once

#include "gl/context.hpp"

namespace gl {

class EglSurfacelessContext final : public Context {
public:
    // Display from eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA),
    // or EGL_DEFAULT_DISPLAY when that extension is missing; the context is
    // current on return. Errors name the EGL error, e.g.
    // "gl::EglSurfacelessContext::create(): eglInitialize failed: EGL_NOT_INITIALIZED".
    static frustum::Result<std::unique_ptr<Context>> create(const ContextOptions& options);

    // Releases the context if current, destroys it, and releases the
    // thread's EGL state when nothing is current any more. The display is
    // shared by all contexts and stays initialized until exit (see .cpp).
    ~EglSurfacelessContext() override;

    frustum::Status make_current() override;
    Proc get_proc_address(const char* name) const override;
    Backend backend() const override { return Backend::Egl; }

private:
    // EGLDisplay and EGLContext are both void*; EGL headers stay private.
    EglSurfacelessContext(ContextOptions options, void* display, void* context);

    void* display_;
    void* context_;
};

} // namespace gl
