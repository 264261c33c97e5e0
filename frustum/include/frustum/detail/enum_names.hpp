// A table of an enum's values and their names, and the two look-ups every
// such table goes through: the name of a value (to_string) and the value of
// a name (parse). The app's enums (effects, mirror methods, cap shapes,
// backends) and gl/'s API enums (gl/enum_name.hpp) are tables of this one
// kind. Not part of the library's API.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace frustum::detail {

template <class Value>
struct EnumName {
    Value value;
    const char* name;
};

// The name of `value` in `table`, or nullptr when the table lacks it (the
// caller words the fallback: "?", "0x1234", "EGL error 12288").
template <class Value, std::size_t N>
constexpr const char* find_enum_name(const EnumName<Value> (&table)[N], Value value) {
    for (const EnumName<Value>& entry : table) {
        if (entry.value == value) {
            return entry.name;
        }
    }
    return nullptr;
}

// The value named `name` in `table`; empty for any other text.
template <class Value, std::size_t N>
constexpr std::optional<Value> find_enum_value(const EnumName<Value> (&table)[N], std::string_view name) {
    for (const EnumName<Value>& entry : table) {
        if (name == entry.name) {
            return entry.value;
        }
    }
    return std::nullopt;
}

} // namespace frustum::detail
