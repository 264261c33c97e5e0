// A GL context, whichever backend made it. The offscreen backends render
// only into framebuffer objects (gl::OffscreenTarget) and have no visible
// surface; gl::GlfwEglWindow (glfw_egl_window.hpp) adds a window's
// framebuffer 0.
//
// Threading: a context is current on the thread that created it (create()
// leaves it current) until another one is made current there. Destroy every
// gl object of a context before the context itself.
#pragma once

#include <frustum/result.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gl {

// Web: the browser's WebGL 2 context (gl/web_context.hpp, emscripten
// builds only); parse_backend() does not offer it.
enum class Backend { Egl, OsMesa, Web };

// "egl" / "osmesa" / "webgl".
std::string_view to_string(Backend backend);
// Inverse of to_string(Backend); anything else is an error listing the choices.
frustum::Result<Backend> parse_backend(std::string_view text);

enum class Api { Gles, GlCore };

// "OpenGL ES" / "OpenGL core".
std::string_view to_string(Api api);

struct Version {
    int major = 0;
    int minor = 0;
};

// "3.2", as messages write a version.
std::string to_string(const Version& version);

// Receives one line per KHR_debug message; called on the GL thread.
using DebugSink = std::function<void(std::string_view)>;

struct ContextOptions {
    // Exact version to request; unset = the highest available
    // (EGL: ES 3.2, 3.1, 3.0; OSMesa: core 4.6 down to 4.3, which has
    // ARB_ES3_compatibility for "#version 300 es" shaders).
    std::optional<Version> gles_version;
    std::optional<Version> gl_version;
    // Requests a debug context and forwards KHR_debug messages to debug_sink
    // (required when debug is true).
    bool debug = false;
    DebugSink debug_sink;
};

// What the driver says about itself, read once when the context is made.
struct ContextInfo {
    Api api = Api::Gles;
    Version version;          // GL_MAJOR_VERSION / GL_MINOR_VERSION
    std::string vendor;       // GL_VENDOR, e.g. "Mesa"
    std::string renderer;     // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version_text; // GL_VERSION, e.g. "OpenGL ES 3.2 Mesa 22.3.6"
    std::string glsl_version; // GL_SHADING_LANGUAGE_VERSION
    std::string extensions;   // every GL_EXTENSIONS entry, space-separated
};

// A version a backend may be asked for: OpenGL ES >= 3.0, core profile >=
// 3.2; otherwise "<where>: gles_version must be >= 3.0, got 2.0" (or
// "gl_version must be >= 3.2 (core profile)").
frustum::Status check_requested_version(Api api, const Version& version, const char* where);

// True when the space-separated `list` holds `token` as a whole entry
// (extension strings: "GL_EXT" does not match "GL_EXT_clip_control").
bool contains_token(std::string_view list, std::string_view token);

// One line, e.g. "OpenGL ES 3.2 Mesa 22.3.6 | Mesa | llvmpipe (...) | 123 extensions".
std::string summary(const ContextInfo& info);

class Context {
public:
    using Proc = void (*)();

    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    virtual ~Context() = default;

    virtual frustum::Status make_current() = 0;
    // Entry point by name ("glDrawArrays"); null when unknown. Some loaders
    // return a stub for any gl* name, so check the extension first.
    virtual Proc get_proc_address(const char* name) const = 0;
    virtual Backend backend() const = 0;

    const ContextOptions& options() const { return options_; }
    const ContextInfo& describe() const { return info_; }
    Api api() const { return info_.api; }
    bool version_at_least(int major, int minor) const;
    // Exact match against one GL_EXTENSIONS entry, e.g. "GL_EXT_clip_control".
    bool has_extension(std::string_view name) const;

protected:
    explicit Context(ContextOptions options) : options_(std::move(options)) {}
    // The versions a backend's create() tries, in order: `requested` alone
    // when set (checked by check_requested_version()), else `highest_first`.
    static frustum::Result<std::vector<Version>> versions_to_try(Api api, const std::optional<Version>& requested,
                                                                 std::vector<Version> highest_first, const char* where);
    // The end of every backend's create(), once the native context exists:
    // makes it current, reads ContextInfo and, with options().debug,
    // installs the debug message callback.
    frustum::Status initialize(Api api, const char* where);

private:
    ContextOptions options_;
    ContextInfo info_;
};

// A context of the given backend, current on the calling thread.
frustum::Result<std::unique_ptr<Context>> create_offscreen_context(Backend backend,
                                                                  const ContextOptions& options);

// EGL first, then OSMesa; if both fail the message holds both reasons.
// `on_fallback` (optional) hears EGL's error before OSMesa is tried: the
// app's one fallback note (frustum-demo's make_context()).
frustum::Result<std::unique_ptr<Context>> create_offscreen_context_with_fallback(
    const ContextOptions& options, const std::function<void(const std::string& egl_error)>& on_fallback = {});

} // namespace gl
