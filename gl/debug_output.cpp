#include "gl/debug_output.hpp"

#include "gl/enum_name.hpp"
#include "gl/gl_api.hpp"

#include <cstring>
#include <string>

namespace gl {
namespace {

template <std::size_t N>
const char* lookup(const EnumName<GLenum> (&table)[N], GLenum value) {
    const char* name = find_enum_name(table, value);
    return name != nullptr ? name : "other";
}

constexpr EnumName<GLenum> kSources[] = {
    {GL_DEBUG_SOURCE_API, "api"},
    {GL_DEBUG_SOURCE_WINDOW_SYSTEM, "window system"},
    {GL_DEBUG_SOURCE_SHADER_COMPILER, "shader compiler"},
    {GL_DEBUG_SOURCE_THIRD_PARTY, "third party"},
    {GL_DEBUG_SOURCE_APPLICATION, "application"},
};
constexpr EnumName<GLenum> kTypes[] = {
    {GL_DEBUG_TYPE_ERROR, "error"},
    {GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR, "deprecated"},
    {GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR, "undefined behaviour"},
    {GL_DEBUG_TYPE_PORTABILITY, "portability"},
    {GL_DEBUG_TYPE_PERFORMANCE, "performance"},
    {GL_DEBUG_TYPE_MARKER, "marker"},
    {GL_DEBUG_TYPE_PUSH_GROUP, "push group"},
    {GL_DEBUG_TYPE_POP_GROUP, "pop group"},
};
constexpr EnumName<GLenum> kSeverities[] = {
    {GL_DEBUG_SEVERITY_HIGH, "high"},
    {GL_DEBUG_SEVERITY_MEDIUM, "medium"},
    {GL_DEBUG_SEVERITY_LOW, "low"},
    {GL_DEBUG_SEVERITY_NOTIFICATION, "notification"},
};

void GL_APIENTRY forward(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                         const GLchar* message, const void* user) {
    const auto& sink = *static_cast<const DebugSink*>(user);
    const std::size_t size = length < 0 ? std::strlen(message) : static_cast<std::size_t>(length);
    sink(std::string("GL debug: ") + lookup(kTypes, type) + ", " + lookup(kSeverities, severity) +
         ", " + lookup(kSources, source) + " #" + std::to_string(id) + ": " +
         std::string(message, size));
}

} // namespace

const char* debug_callback_entry_point(const Context& context) {
    if (context.api() == Api::Gles) {
        if (context.version_at_least(3, 2)) {
            return "glDebugMessageCallback";
        }
        return context.has_extension("GL_KHR_debug") ? "glDebugMessageCallbackKHR" : nullptr;
    }
    const bool core = context.version_at_least(4, 3) || context.has_extension("GL_KHR_debug");
    return core ? "glDebugMessageCallback" : nullptr;
}

frustum::Status install_debug_output(const Context& context, const DebugSink& sink) {
    const char* name = debug_callback_entry_point(context);
    if (name == nullptr) {
        return frustum::Error{"gl::install_debug_output(): debug output needs GL_KHR_debug, "
                              "which " + context.describe().version_text + " lacks"};
    }
    const auto set_callback =
        reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKPROC>(context.get_proc_address(name));
    const auto enable = reinterpret_cast<PFNGLENABLEPROC>(context.get_proc_address("glEnable"));
    if (set_callback == nullptr || enable == nullptr) {
        return frustum::Error{std::string("gl::install_debug_output(): ") + name +
                              " or glEnable not found"};
    }
    enable(GL_DEBUG_OUTPUT);
    enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    set_callback(forward, &sink);
    return {};
}

} // namespace gl
