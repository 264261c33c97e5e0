#include "gl/errors.hpp"

#include "gl/enum_name.hpp"

#include <cstdio>

namespace gl {
namespace {

template <std::size_t N>
std::string lookup(const EnumName<GLenum> (&table)[N], GLenum value) {
    if (const char* name = find_enum_name(table, value)) {
        return name;
    }
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", value);
    return hex;
}

constexpr EnumName<GLenum> kErrors[] = {
    {GL_NO_ERROR, "GL_NO_ERROR"},
    {GL_INVALID_ENUM, "GL_INVALID_ENUM"},
    {GL_INVALID_VALUE, "GL_INVALID_VALUE"},
    {GL_INVALID_OPERATION, "GL_INVALID_OPERATION"},
    {GL_INVALID_FRAMEBUFFER_OPERATION, "GL_INVALID_FRAMEBUFFER_OPERATION"},
    {GL_OUT_OF_MEMORY, "GL_OUT_OF_MEMORY"},
    {GL_STACK_OVERFLOW, "GL_STACK_OVERFLOW"},
    {GL_STACK_UNDERFLOW, "GL_STACK_UNDERFLOW"},
    {GL_CONTEXT_LOST, "GL_CONTEXT_LOST"},
};

constexpr EnumName<GLenum> kFramebufferStatuses[] = {
    {GL_FRAMEBUFFER_COMPLETE, "GL_FRAMEBUFFER_COMPLETE"},
    {GL_FRAMEBUFFER_UNDEFINED, "GL_FRAMEBUFFER_UNDEFINED"},
    {GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"},
    {GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"},
    {GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS, "GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS"},
    {GL_FRAMEBUFFER_UNSUPPORTED, "GL_FRAMEBUFFER_UNSUPPORTED"},
    {GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE, "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE"},
    {GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS, "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS"},
};

// A lost context may report its error forever; stop after this many.
constexpr int kMaxErrorFlags = 8;

} // namespace

std::string error_name(GLenum error) { return lookup(kErrors, error); }

std::string framebuffer_status_name(GLenum status) { return lookup(kFramebufferStatuses, status); }

frustum::Status check_error(const Functions& fn, const char* where) {
    std::string names;
    int count = 0;
    for (GLenum error = fn.GetError(); error != GL_NO_ERROR && count < kMaxErrorFlags;
         error = fn.GetError(), ++count) {
        names += (names.empty() ? "" : ", ") + error_name(error);
    }
    if (names.empty()) {
        return {};
    }
    return frustum::Error{std::string(where) + (count > 1 ? ": GL errors " : ": GL error ") + names};
}

frustum::Status check_framebuffer_complete(const Functions& fn, GLenum target, const char* where) {
    const GLenum status = fn.CheckFramebufferStatus(target);
    if (status == GL_FRAMEBUFFER_COMPLETE) {
        return {};
    }
    return frustum::Error{std::string(where) + ": framebuffer incomplete: " +
                          framebuffer_status_name(status)};
}

} // namespace gl
