// The offscreen backends behind create_offscreen_context() (context.hpp).
// A file of its own so that a build without EGL and OSMesa (the browser,
// gl/web_context.hpp) links context.cpp without them.
#include "gl/context.hpp"

#include "gl/egl_surfaceless_context.hpp"
#include "gl/osmesa_context.hpp"

namespace gl {

frustum::Result<std::unique_ptr<Context>> create_offscreen_context(Backend backend,
                                                                  const ContextOptions& options) {
    switch (backend) {
    case Backend::Egl: return EglSurfacelessContext::create(options);
    case Backend::OsMesa: return OsMesaContext::create(options);
    case Backend::Web: break;
    }
    return frustum::Error{"gl::create_offscreen_context(): backend 'webgl' is the browser's canvas "
                          "context (gl::WebGlContext), not an offscreen one; use 'egl' or 'osmesa'"};
}

frustum::Result<std::unique_ptr<Context>> create_offscreen_context_with_fallback(
    const ContextOptions& options, const std::function<void(const std::string& egl_error)>& on_fallback) {
    auto egl = EglSurfacelessContext::create(options);
    if (egl) {
        return egl;
    }
    if (on_fallback) {
        on_fallback(egl.error());
    }
    auto osmesa = OsMesaContext::create(options);
    if (osmesa) {
        return osmesa;
    }
    return frustum::Error{"gl::create_offscreen_context_with_fallback(): no backend works; egl: " +
                          egl.error() + "; osmesa: " + osmesa.error()};
}

} // namespace gl
