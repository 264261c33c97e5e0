// KHR_debug output forwarded to a caller's sink, one line per message:
//   "GL debug: error, high, api #1: GL_INVALID_ENUM in glEnable(GL_...)"
#pragma once

#include "gl/context.hpp"

#include <frustum/result.hpp>

namespace gl {

// The name glDebugMessageCallback goes by in this context ("...KHR" on
// GLES < 3.2 with GL_KHR_debug), or nullptr when the context has no KHR_debug.
const char* debug_callback_entry_point(const Context& context);

// Enables synchronous debug output on the current context and sends every
// message to `sink`, which must outlive the context (Context keeps its own
// copy in options(), which is what Context::initialize() passes).
frustum::Status install_debug_output(const Context& context, const DebugSink& sink);

} // namespace gl
