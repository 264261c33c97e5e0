// Clip-space depth in [0, 1] (GL_ZERO_TO_ONE) instead of GL's [-1, 1], for
// matrices built with DepthRange::ZeroToOne. Needs GL_EXT_clip_control on
// GLES or GL 4.5 / GL_ARB_clip_control on desktop; without it a caller
// converts its matrices to DepthRange::MinusOneToOne instead.
#pragma once

#include "gl/context.hpp"
#include "gl/functions.hpp"

#include <frustum/result.hpp>

namespace gl {

// "glClipControlEXT" (GLES), "glClipControl" (desktop), or nullptr when the
// context has no clip control.
const char* clip_control_entry_point(const Context& context);

bool supports_zero_to_one_depth(const Functions& fn, const Context& context);

// enable: GL_LOWER_LEFT + GL_ZERO_TO_ONE; otherwise GL's default
// GL_LOWER_LEFT + GL_NEGATIVE_ONE_TO_ONE. Enabling without support is an
// error; disabling without support succeeds, since [-1, 1] is then the only mode.
frustum::Status set_depth_zero_to_one(const Functions& fn, bool enable);

} // namespace gl
