// A table of an API's enum values and their names, and the look-up every
// such table in gl/ goes through (GL errors, framebuffer statuses, KHR_debug
// fields, EGL errors): the app's one kind of name table
// (frustum/detail/enum_names.hpp). No GL or EGL header: `Value` is the API's own type.
#pragma once

#include <frustum/detail/enum_names.hpp>

namespace gl {

using frustum::detail::EnumName;
using frustum::detail::find_enum_name;

} // namespace gl
