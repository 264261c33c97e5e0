#include "gl/context.hpp"

#include "gl/debug_output.hpp"
#include "gl/enum_name.hpp"
#include "gl/gl_api.hpp"

#include <algorithm>

namespace gl {
namespace {

std::string gl_string(PFNGLGETSTRINGPROC get_string, GLenum name) {
    const GLubyte* text = get_string(name);
    return text == nullptr ? std::string() : reinterpret_cast<const char*>(text);
}

} // namespace

constexpr EnumName<Backend> kBackendNames[] = {
    {Backend::Egl, "egl"}, {Backend::OsMesa, "osmesa"}, {Backend::Web, "webgl"}};

std::string_view to_string(Backend backend) {
    const char* name = find_enum_name(kBackendNames, backend);
    return name ? name : "unknown";
}

frustum::Result<Backend> parse_backend(std::string_view text) {
    // --backend names the offscreen ones only.
    if (auto backend = frustum::detail::find_enum_value(kBackendNames, text); backend && *backend != Backend::Web) {
        return *backend;
    }
    return frustum::Error{"gl::parse_backend(): backend must be 'egl' or 'osmesa', got '" +
                          std::string(text) + "'"};
}

std::string_view to_string(Api api) {
    return api == Api::Gles ? "OpenGL ES" : "OpenGL core";
}

std::string to_string(const Version& version) {
    return std::to_string(version.major) + "." + std::to_string(version.minor);
}

frustum::Status check_requested_version(Api api, const Version& version, const char* where) {
    const bool es = api == Api::Gles;
    const Version lowest = es ? Version{3, 0} : Version{3, 2};
    if (version.major > lowest.major || (version.major == lowest.major && version.minor >= lowest.minor)) {
        return {};
    }
    return frustum::Error{std::string(where) + (es ? ": gles_version must be >= 3.0, got " : ": gl_version must be >= 3.2 (core profile), got ") +
                          to_string(version)};
}

bool contains_token(std::string_view list, std::string_view token) {
    for (std::size_t start = 0; !token.empty() && start <= list.size();) {
        const std::size_t end = std::min(list.find(' ', start), list.size());
        if (list.substr(start, end - start) == token) {
            return true;
        }
        start = end + 1;
    }
    return false;
}

std::string summary(const ContextInfo& info) {
    // initialize() joins the names with single spaces.
    const auto count = info.extensions.empty()
                           ? 0
                           : std::count(info.extensions.begin(), info.extensions.end(), ' ') + 1;
    return info.version_text + " | " + info.vendor + " | " + info.renderer + " | " +
           std::to_string(count) + " extensions";
}

bool Context::version_at_least(int major, int minor) const {
    const Version& v = info_.version;
    return v.major > major || (v.major == major && v.minor >= minor);
}

bool Context::has_extension(std::string_view name) const {
    return contains_token(info_.extensions, name);
}

frustum::Result<std::vector<Version>> Context::versions_to_try(Api api, const std::optional<Version>& requested,
                                                              std::vector<Version> highest_first, const char* where) {
    if (!requested) {
        return highest_first;
    }
    if (auto checked = check_requested_version(api, *requested, where); !checked) {
        return checked.take_error();
    }
    return std::vector<Version>{*requested};
}

frustum::Status Context::initialize(Api api, const char* where) {
    if (auto current = make_current(); !current) {
        return current;
    }
    const auto get_string = reinterpret_cast<PFNGLGETSTRINGPROC>(get_proc_address("glGetString"));
    const auto get_stringi = reinterpret_cast<PFNGLGETSTRINGIPROC>(get_proc_address("glGetStringi"));
    const auto get_integerv =
        reinterpret_cast<PFNGLGETINTEGERVPROC>(get_proc_address("glGetIntegerv"));
    if (get_string == nullptr || get_stringi == nullptr || get_integerv == nullptr) {
        return frustum::Error{std::string(where) +
                              ": glGetString, glGetStringi or glGetIntegerv not found"};
    }
    info_.api = api;
    get_integerv(GL_MAJOR_VERSION, &info_.version.major);
    get_integerv(GL_MINOR_VERSION, &info_.version.minor);
    info_.vendor = gl_string(get_string, GL_VENDOR);
    info_.renderer = gl_string(get_string, GL_RENDERER);
    info_.version_text = gl_string(get_string, GL_VERSION);
    info_.glsl_version = gl_string(get_string, GL_SHADING_LANGUAGE_VERSION);
    GLint count = 0;
    get_integerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLubyte* name = get_stringi(GL_EXTENSIONS, static_cast<GLuint>(i));
        if (name != nullptr) {
            info_.extensions += (info_.extensions.empty() ? "" : " ");
            info_.extensions += reinterpret_cast<const char*>(name);
        }
    }
    if (!options_.debug) {
        return {};
    }
    if (!options_.debug_sink) {
        return frustum::Error{std::string(where) + ": options.debug needs a debug_sink"};
    }
    return install_debug_output(*this, options_.debug_sink);
}

} // namespace gl
