// Error text in the project's one format:
//   "frustum::perspective(): near must be > 0, got near=-0.1 far=100"
// Numbers are printed in their own type's shortest round-trip form.
#pragma once

#include "frustum/detail/shortest_text.hpp"
#include "frustum/result.hpp"
#include "frustum/types.hpp"

#include <charconv>
#if defined(__EMSCRIPTEN__)
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>
#endif
#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace frustum::detail {

template <class T>
std::string number(T value) {
#if !defined(__cpp_lib_to_chars) || __cpp_lib_to_chars < 201611L
    // No floating-point std::to_chars (libc++ 13, emscripten): the same text
    // from snprintf/strtod (shortest_text.hpp).
    if constexpr (std::is_floating_point_v<T>) {
        return shortest_text_portable(value);
    } else
#endif
    {
        char buffer[64];
        const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
        return std::string(buffer, end);
    }
}

template <class T>
std::string vector_text(const Vec3<T>& v) {
    return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}

template <class T>
std::string vector_text(const Vec4<T>& v) {
    return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ", " + number(v.w) + ")";
}

// "frustum::<function>(): <rule>" + ", got a=1 b=2" when values are given.
template <class T>
Error error(std::string_view function, std::string_view rule,
            std::initializer_list<std::pair<std::string_view, T>> values = {}) {
    std::string text = "frustum::";
    text += function;
    text += "(): ";
    text += rule;
    const char* separator = ", got ";
    for (const auto& [name, value] : values) {
        text += separator;
        text += name;
        text += '=';
        text += number(value);
        separator = " ";
    }
    return Error{text};
}

// Same, with free-form detail text after the rule.
inline Error error_text(std::string_view function, std::string_view rule, std::string_view detail) {
    std::string text = "frustum::";
    text += function;
    text += "(): ";
    text += rule;
    if (!detail.empty()) {
        text += ", got ";
        text += detail;
    }
    return Error{text};
}

} // namespace frustum::detail
