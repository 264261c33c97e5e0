#include "gl/egl_surfaceless_context.hpp"

#include "gl/enum_name.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>
#include <string_view>
#include <vector>

namespace gl {
namespace {

constexpr const char* kCreate = "gl::EglSurfacelessContext::create()";

std::string egl_error_name(EGLint error) {
    static constexpr EnumName<EGLint> kNames[] = {
        {EGL_SUCCESS, "EGL_SUCCESS"},
        {EGL_NOT_INITIALIZED, "EGL_NOT_INITIALIZED"},
        {EGL_BAD_ACCESS, "EGL_BAD_ACCESS"},
        {EGL_BAD_ALLOC, "EGL_BAD_ALLOC"},
        {EGL_BAD_ATTRIBUTE, "EGL_BAD_ATTRIBUTE"},
        {EGL_BAD_CONFIG, "EGL_BAD_CONFIG"},
        {EGL_BAD_CONTEXT, "EGL_BAD_CONTEXT"},
        {EGL_BAD_CURRENT_SURFACE, "EGL_BAD_CURRENT_SURFACE"},
        {EGL_BAD_DISPLAY, "EGL_BAD_DISPLAY"},
        {EGL_BAD_MATCH, "EGL_BAD_MATCH"},
        {EGL_BAD_NATIVE_PIXMAP, "EGL_BAD_NATIVE_PIXMAP"},
        {EGL_BAD_NATIVE_WINDOW, "EGL_BAD_NATIVE_WINDOW"},
        {EGL_BAD_PARAMETER, "EGL_BAD_PARAMETER"},
        {EGL_BAD_SURFACE, "EGL_BAD_SURFACE"},
        {EGL_CONTEXT_LOST, "EGL_CONTEXT_LOST"},
    };
    if (const char* name = find_enum_name(kNames, error)) {
        return name;
    }
    return "EGL error " + std::to_string(error);
}

// "<where>: <what> failed: EGL_BAD_..." with the thread's last EGL error.
frustum::Error egl_failure(const char* where, const std::string& what) {
    return frustum::Error{std::string(where) + ": " + what + " failed: " +
                          egl_error_name(eglGetError())};
}

// EGL extension strings may be null before eglInitialize.
bool has_token(const char* list, std::string_view token) {
    return list != nullptr && contains_token(list, token);
}

frustum::Result<EGLDisplay> open_display() {
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string what = "eglGetDisplay(EGL_DEFAULT_DISPLAY)";
    if (has_token(client_extensions, "EGL_EXT_platform_base") &&
        has_token(client_extensions, "EGL_MESA_platform_surfaceless")) {
        what = "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)";
        const auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (get_platform_display != nullptr) {
            display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        }
    } else {
        display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    }
    if (display == EGL_NO_DISPLAY) {
        return egl_failure(kCreate, "no EGL display: " + what);
    }
    if (!eglInitialize(display, nullptr, nullptr)) {
        return egl_failure(kCreate, "no usable EGL device: eglInitialize");
    }
    return display;
}

// The display is one object per process, shared by every context, and
// stays initialized until exit: eglTerminate is not reference counted (it
// would pull the display from under other live contexts), and Mesa's
// eglTerminate unloads the driver, leaking a little memory per cycle.
const frustum::Result<EGLDisplay>& process_display() {
    static const frustum::Result<EGLDisplay> opened = open_display();
    return opened;
}

} // namespace

EglSurfacelessContext::EglSurfacelessContext(ContextOptions options, void* display, void* context)
    : Context(std::move(options)), display_(display), context_(context) {}

EglSurfacelessContext::~EglSurfacelessContext() {
    if (context_ != EGL_NO_CONTEXT) {
        if (eglGetCurrentContext() == context_) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        eglDestroyContext(display_, context_);
    }
    if (eglGetCurrentContext() == EGL_NO_CONTEXT) {
        eglReleaseThread();
    }
}

frustum::Result<std::unique_ptr<Context>> EglSurfacelessContext::create(
    const ContextOptions& options) {
    auto versions = versions_to_try(Api::Gles, options.gles_version, {{3, 2}, {3, 1}, {3, 0}}, kCreate);
    if (!versions) {
        return versions.take_error();
    }
    if (!process_display()) {
        return frustum::Error{process_display().error()};
    }
    const EGLDisplay display = *process_display();
    // Destroys the context on every early return below.
    std::unique_ptr<EglSurfacelessContext> self(
        new EglSurfacelessContext(options, display, EGL_NO_CONTEXT));
    if (!has_token(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        return frustum::Error{std::string(kCreate) + ": EGL display lacks EGL_KHR_surfaceless_context (" +
                              eglQueryString(display, EGL_VENDOR) + " EGL " +
                              eglQueryString(display, EGL_VERSION) + ")"};
    }
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
        return egl_failure(kCreate, "eglBindAPI(EGL_OPENGL_ES_API)");
    }
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
                                        EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint config_count = 0;
    if (!eglChooseConfig(display, config_attributes, &config, 1, &config_count)) {
        return egl_failure(kCreate, "eglChooseConfig(EGL_OPENGL_ES3_BIT)");
    }
    if (config_count == 0) {
        return frustum::Error{std::string(kCreate) + ": no EGLConfig renders OpenGL ES 3"};
    }
    std::string failures;
    for (const Version& v : *versions) {
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, v.major,
                                     EGL_CONTEXT_MINOR_VERSION, v.minor,
                                     EGL_CONTEXT_OPENGL_DEBUG, options.debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
        self->context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
        if (self->context_ != EGL_NO_CONTEXT) {
            break;
        }
        failures += (failures.empty() ? "" : ", ") + to_string(v) + ": " + egl_error_name(eglGetError());
    }
    if (self->context_ == EGL_NO_CONTEXT) {
        return frustum::Error{std::string(kCreate) + ": no OpenGL ES 3.x context, eglCreateContext failed for " +
                              failures};
    }
    if (auto ready = self->initialize(Api::Gles, kCreate); !ready) {
        return frustum::Error{ready.error()};
    }
    return std::unique_ptr<Context>(std::move(self));
}

frustum::Status EglSurfacelessContext::make_current() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
        return egl_failure("gl::EglSurfacelessContext::make_current()", "eglMakeCurrent");
    }
    return {};
}

Context::Proc EglSurfacelessContext::get_proc_address(const char* name) const {
    return eglGetProcAddress(name);
}

} // namespace gl
