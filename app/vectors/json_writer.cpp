#include "vectors/json_writer.hpp"

#include <frustum/detail/errors.hpp>

#include "vectors/json_escapes.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <cstdio>

namespace vectors {

namespace {

using nlohmann::ordered_json;

void write_string(std::string& out, const std::string& s) {
    out += '"';
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        const JsonEscape* escape = std::find_if(std::begin(kJsonEscapes), std::end(kJsonEscapes),
                                                [ch](const JsonEscape& e) { return e.character == ch; });
        if (escape != std::end(kJsonEscapes)) {
            out += '\\';
            out += escape->letter;
        } else if (c < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
            out += buffer;
        } else {
            out += ch; // UTF-8 passes through (the reader validated it)
        }
    }
    out += '"';
}

bool is_scalar(const ordered_json& v) { return !v.is_array() && !v.is_object(); }

bool all_scalars(const ordered_json& array) {
    for (const auto& v : array) {
        if (!is_scalar(v)) {
            return false;
        }
    }
    return true;
}

void write_value(std::string& out, const ordered_json& v, int indent) {
    const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
    const std::string close_pad(static_cast<std::size_t>(indent), ' ');
    switch (v.type()) {
    case ordered_json::value_t::null: out += "null"; return;
    case ordered_json::value_t::boolean: out += v.get<bool>() ? "true" : "false"; return;
    case ordered_json::value_t::string: write_string(out, v.get_ref<const std::string&>()); return;
    case ordered_json::value_t::number_integer: out += std::to_string(v.get<long long>()); return;
    case ordered_json::value_t::number_unsigned: out += std::to_string(v.get<unsigned long long>()); return;
    case ordered_json::value_t::number_float: out += number_text(v.get<double>()); return;
    case ordered_json::value_t::array:
        if (v.empty()) {
            out += "[]";
        } else if (all_scalars(v)) {
            out += '[';
            for (std::size_t i = 0; i < v.size(); ++i) {
                out += i ? ", " : "";
                write_value(out, v[i], indent);
            }
            out += ']';
        } else {
            out += "[\n";
            for (std::size_t i = 0; i < v.size(); ++i) {
                out += pad;
                write_value(out, v[i], indent + 2);
                out += i + 1 < v.size() ? ",\n" : "\n";
            }
            out += close_pad + "]";
        }
        return;
    case ordered_json::value_t::object: {
        if (v.empty()) {
            out += "{}";
            return;
        }
        out += "{\n";
        std::size_t i = 0;
        for (const auto& item : v.items()) {
            out += pad;
            write_string(out, item.key());
            out += ": ";
            write_value(out, item.value(), indent + 2);
            out += ++i < v.size() ? ",\n" : "\n";
        }
        out += close_pad + "}";
        return;
    }
    default: out += "null"; return; // binary / discarded: never built here
    }
}

} // namespace

std::string number_text(double value) {
    return frustum::detail::number(value); // std::to_chars's text, also where libc++ lacks it
}

std::string write_json(const nlohmann::ordered_json& value) {
    std::string out;
    write_value(out, value, 0);
    out += '\n';
    return out;
}

} // namespace vectors
