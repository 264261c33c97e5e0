// GL error flags and framebuffer status as named errors.
#pragma once

#include "gl/functions.hpp"

#include <frustum/result.hpp>

#include <string>

namespace gl {

// "GL_INVALID_ENUM", ...; unknown values as hex, "0x1234".
std::string error_name(GLenum error);
// "GL_FRAMEBUFFER_COMPLETE", "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT", ...
std::string framebuffer_status_name(GLenum status);

// Drains glGetError. Ok when no flag was set, otherwise
// "<where>: GL error GL_INVALID_VALUE" (every flag that was set, in order).
frustum::Status check_error(const Functions& fn, const char* where);

// Ok when the framebuffer bound to `target` is complete, otherwise
// "<where>: framebuffer incomplete: GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT".
frustum::Status check_framebuffer_complete(const Functions& fn, GLenum target, const char* where);

} // namespace gl
