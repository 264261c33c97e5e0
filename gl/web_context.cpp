#include "gl/web_context.hpp"

// The GLES 3 prototypes, which every other gl/ file leaves out (gl_api.hpp):
// here they are emscripten's WebGL 2 functions, whose addresses fill the table.
#undef GL_GLES_PROTOTYPES
#define GL_GLES_PROTOTYPES 1
#include <GLES3/gl32.h>

#include "gl/functions.hpp"

#include <emscripten/html5.h>

#include <cstring>

namespace gl {

frustum::Result<std::unique_ptr<WebGlContext>> WebGlContext::create(const std::string& canvas,
                                                                    const ContextOptions& options) {
    const std::string where = "gl::WebGlContext::create()";
    if (options.debug) {
        return frustum::Error{where + ": options.debug needs KHR_debug, which WebGL 2 does not have"};
    }
    if (options.gl_version || (options.gles_version && (options.gles_version->major != 3 ||
                                                        options.gles_version->minor != 0))) {
        return frustum::Error{where + ": WebGL 2 is OpenGL ES 3.0; no other version can be requested"};
    }
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.alpha = EM_FALSE;
    attributes.depth = EM_FALSE;
    attributes.stencil = EM_FALSE;
    attributes.antialias = EM_FALSE;
    attributes.premultipliedAlpha = EM_FALSE;
    // The frame stays in the canvas until the next one (screenshots read it).
    attributes.preserveDrawingBuffer = EM_TRUE;
    attributes.failIfMajorPerformanceCaveat = EM_FALSE;
    const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE handle = emscripten_webgl_create_context(canvas.c_str(), &attributes);
    if (handle <= 0) {
        return frustum::Error{where + ": no WebGL 2 context on '" + canvas + "' (emscripten error " +
                              std::to_string(handle) + ")"};
    }
    std::unique_ptr<WebGlContext> context(new WebGlContext(options, canvas, handle));
    if (auto initialized = context->initialize(Api::Gles, "gl::WebGlContext::create()"); !initialized) {
        return frustum::Error{initialized.error()};
    }
    return context;
}

WebGlContext::~WebGlContext() {
    emscripten_webgl_destroy_context(handle_);
}

frustum::Status WebGlContext::make_current() {
    const EMSCRIPTEN_RESULT result = emscripten_webgl_make_context_current(handle_);
    if (result != EMSCRIPTEN_RESULT_SUCCESS) {
        return frustum::Error{"gl::WebGlContext::make_current(): '" + canvas_ + "' failed (emscripten error " +
                              std::to_string(result) + ")"};
    }
    return {};
}

Context::Proc WebGlContext::get_proc_address(const char* name) const {
    // static_cast checks that emscripten's prototype has the table's type.
#define FRUSTUM_GL_WEB_ENTRY(type, entry)                                                \
    if (std::strcmp(name, "gl" #entry) == 0) {                                          \
        return reinterpret_cast<Proc>(static_cast<type>(&gl##entry));                   \
    }
    FRUSTUM_GL_REQUIRED_FUNCTIONS(FRUSTUM_GL_WEB_ENTRY)
#undef FRUSTUM_GL_WEB_ENTRY
    return nullptr;
}

} // namespace gl
