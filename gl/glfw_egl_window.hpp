// A desktop window with an OpenGL ES 3 context made through EGL (GLFW with
// GLFW_OPENGL_ES_API + GLFW_EGL_CONTEXT_API), or a desktop OpenGL core one
// (GLFW_OPENGL_API, core profile, also through EGL), as a gl::Context. The
// project's "#version 300 es" shaders compile on desktop 4.3+ core through
// ARB_ES3_compatibility, as on the OSMesa backend. Unlike the
// offscreen backends it has a visible default framebuffer (0), shown by
// swap_buffers(). Input arrives as gl::InputEvent values (window_input.hpp);
// no GLFW header appears here.
//
// create() initializes GLFW, which then stays initialized until the
// process exits, like the EGL display of EglSurfacelessContext:
// glfwTerminate() would call eglTerminate(), and Mesa's eglTerminate unloads
// its driver and leaks a little memory each time (LeakSanitizer reports it
// from an unloaded module, so it cannot be suppressed by name). Use the
// window on the thread that created it (GLFW's main-thread rule).
#pragma once

#include "gl/context.hpp"
#include "gl/window_input.hpp"

#include <frustum/result.hpp>

#include <memory>
#include <string>
#include <vector>

namespace gl {

struct WindowOptions {
    std::string title = "frustum";
    int width = 640; // screen coordinates; the framebuffer may be larger (high DPI)
    int height = 360;
    // Api::Gles: OpenGL ES; Api::GlCore: desktop OpenGL, core profile (it
    // has GL_SAMPLES_PASSED, counting occlusion queries).
    Api api = Api::Gles;
    // gles_version (ES) / gl_version (core): the version to ask for, unset =
    // 3.0 / 4.3 or later (the driver picks, e.g. 3.2 / 4.5). debug +
    // debug_sink as for the offscreen contexts.
    ContextOptions context;
    bool vsync = true; // swap interval 1 (0: as fast as possible)
};

struct FramebufferSize {
    int width_px = 0;
    int height_px = 0;
};

class GlfwEglWindow final : public Context {
public:
    // The window is shown and its context current on return. Errors name the
    // reason, e.g. "gl::GlfwEglWindow::create(): no display (DISPLAY is not
    // set; GLFW: X11: The DISPLAY environment variable is missing)" or
    // "gl::GlfwEglWindow::create(): glfwCreateWindow failed for OpenGL ES 3.0
    // through EGL (GLFW: EGL: Failed to create context: ...)" (or "OpenGL core 4.3").
    static frustum::Result<std::unique_ptr<GlfwEglWindow>> create(const WindowOptions& options);

    // Destroys the window and its context (GLFW stays initialized, see above).
    ~GlfwEglWindow() override;

    frustum::Status make_current() override;
    Proc get_proc_address(const char* name) const override;
    // The context is an EGL one (on the window system's display).
    Backend backend() const override { return Backend::Egl; }

    // True once the user closed the window (or request_close() was called).
    bool should_close() const;
    void request_close();

    // Processes pending window-system events and returns them in order.
    std::vector<InputEvent> poll_events();
    // Waits until some event arrives (for a minimized window), then as poll_events().
    std::vector<InputEvent> wait_events();

    FramebufferSize framebuffer_size() const;
    void set_title(const std::string& title);
    // Shows the back buffer; its contents are undefined afterwards.
    void swap_buffers();

private:
    GlfwEglWindow(ContextOptions options, void* window);
    // GLFW callbacks (in the .cpp) append here through the window's user pointer.
    friend struct GlfwCallbacks;

    void* window_; // GLFWwindow*
    std::vector<InputEvent> pending_;
};

} // namespace gl
