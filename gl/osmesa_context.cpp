#include "gl/osmesa_context.hpp"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <string>
#include <vector>

namespace gl {
namespace {

constexpr const char* kCreate = "gl::OsMesaContext::create()";

// The few OSMesa entry points we use, resolved from a dlopen()ed library
// so that OSMesa's GL symbols never meet EGL/GLES ones at link time.
struct OsMesaApi {
    decltype(&OSMesaCreateContextAttribs) create_context_attribs;
    decltype(&OSMesaDestroyContext) destroy_context;
    decltype(&OSMesaMakeCurrent) make_current;
    decltype(&OSMesaGetCurrentContext) get_current_context;
    decltype(&OSMesaGetProcAddress) get_proc_address;
};

template <class F>
bool resolve(void* library, const char* name, F& function) {
    function = reinterpret_cast<F>(dlsym(library, name));
    return function != nullptr;
}

frustum::Result<OsMesaApi> load_api() {
    void* library = nullptr;
    std::string reasons;
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"}) {
        library = dlopen(name, RTLD_NOW | RTLD_LOCAL);
        if (library != nullptr) {
            break;
        }
        reasons += (reasons.empty() ? "" : "; ") + std::string(dlerror());
    }
    if (library == nullptr) {
        return frustum::Error{std::string(kCreate) + ": cannot load OSMesa: " + reasons};
    }
    OsMesaApi api{};
    const bool complete = resolve(library, "OSMesaCreateContextAttribs", api.create_context_attribs) &&
                          resolve(library, "OSMesaDestroyContext", api.destroy_context) &&
                          resolve(library, "OSMesaMakeCurrent", api.make_current) &&
                          resolve(library, "OSMesaGetCurrentContext", api.get_current_context) &&
                          resolve(library, "OSMesaGetProcAddress", api.get_proc_address);
    if (!complete) {
        return frustum::Error{std::string(kCreate) + ": OSMesa lacks an entry point: " + dlerror()};
    }
    return api;
}

// Loaded once; unloading Mesa while the process runs is not supported.
const frustum::Result<OsMesaApi>& osmesa_api() {
    static const frustum::Result<OsMesaApi> loaded = load_api();
    return loaded;
}

} // namespace

OsMesaContext::OsMesaContext(ContextOptions options, void* context)
    : Context(std::move(options)), context_(context) {}

OsMesaContext::~OsMesaContext() {
    if (context_ == nullptr) {
        return;
    }
    const OsMesaApi& osmesa = *osmesa_api();
    if (osmesa.get_current_context() == context_) {
        osmesa.make_current(nullptr, nullptr, 0, 0, 0);
    }
    osmesa.destroy_context(static_cast<OSMesaContext>(context_));
}

frustum::Result<std::unique_ptr<Context>> OsMesaContext::create(const ContextOptions& options) {
    auto versions = versions_to_try(Api::GlCore, options.gl_version, {{4, 6}, {4, 5}, {4, 4}, {4, 3}}, kCreate);
    if (!versions) {
        return versions.take_error();
    }
    if (!osmesa_api()) {
        return frustum::Error{osmesa_api().error()};
    }
    const OsMesaApi& osmesa = *osmesa_api();
    std::unique_ptr<OsMesaContext> self(new OsMesaContext(options, nullptr));
    std::string tried;
    for (const Version& v : *versions) {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS, 0,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, v.major,
                                  OSMESA_CONTEXT_MINOR_VERSION, v.minor,
                                  0};
        self->context_ = osmesa.create_context_attribs(attributes, nullptr);
        if (self->context_ != nullptr) {
            break;
        }
        tried += (tried.empty() ? "" : ", ") + to_string(v);
    }
    if (self->context_ == nullptr) {
        return frustum::Error{std::string(kCreate) +
                              ": no OpenGL core context, OSMesaCreateContextAttribs failed for " + tried};
    }
    if (auto ready = self->initialize(Api::GlCore, kCreate); !ready) {
        return frustum::Error{ready.error()};
    }
    return std::unique_ptr<Context>(std::move(self));
}

frustum::Status OsMesaContext::make_current() {
    if (!osmesa_api()->make_current(static_cast<OSMesaContext>(context_), pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
        return frustum::Error{"gl::OsMesaContext::make_current(): OSMesaMakeCurrent failed (1x1 RGBA8 buffer)"};
    }
    return {};
}

Context::Proc OsMesaContext::get_proc_address(const char* name) const {
    return osmesa_api()->get_proc_address(name);
}

} // namespace gl
