// Desktop OpenGL core profile through OSMesa (Mesa's software off-screen
// library), loaded with dlopen() at run time. Renders into framebuffer
// objects; OSMesa's own colour buffer is a single unused pixel.
#pragma once

#include "gl/context.hpp"

#include <array>

namespace gl {

class OsMesaContext final : public Context {
public:
    // Core profile, options.gl_version or 4.6 down to 4.3; current on return.
    // Errors say what failed, e.g.
    // "gl::OsMesaContext::create(): cannot load OSMesa: libOSMesa.so.8: cannot open shared object file".
    static frustum::Result<std::unique_ptr<Context>> create(const ContextOptions& options);

    // Releases the context if current and destroys it. libOSMesa stays
    // loaded for the life of the process.
    ~OsMesaContext() override;

    frustum::Status make_current() override;
    Proc get_proc_address(const char* name) const override;
    Backend backend() const override { return Backend::OsMesa; }

private:
    // `context` is an OSMesaContext; the OSMesa header stays private.
    OsMesaContext(ContextOptions options, void* context);

    void* context_;
    std::array<unsigned char, 4> pixel_{}; // OSMesa's colour buffer: 1x1 RGBA8
};

} // namespace gl
