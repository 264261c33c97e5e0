// A table of an API's enum values and their names, and the look-up every
// such table in gl/ goes through (GL errors, framebuffer statuses, KHR_debug
// fields, EGL errors). No GL or EGL header: `Value` is the API's own type.
#pragma once

#include <cstddef>

namespace gl {

template <class Value>
struct EnumName {
    Value value;
    const char* name;
};

// The name of `value` in `table`, or nullptr when the table lacks it (the
// caller words the fallback: "other", "0x1234", "EGL error 12288").
template <class Value, std::size_t N>
const char* find_enum_name(const EnumName<Value> (&table)[N], Value value) {
    for (const EnumName<Value>& entry : table) {
        if (entry.value == value) {
            return entry.name;
        }
    }
    return nullptr;
}

} // namespace gl
