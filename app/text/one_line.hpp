// Error messages are one line: text that comes from the input (a uri, a node
// name, a JSON key) is shown with its control characters escaped
// (\n, \r, \t, \xNN). Header-only; used by app/scene and app/vectors.
#pragma once

#include <string>

namespace text {

inline std::string one_line(const std::string& text) {
    static const char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '\n') {
            out += "\\n";
        } else if (ch == '\r') {
            out += "\\r";
        } else if (ch == '\t') {
            out += "\\t";
        } else if (byte < 0x20 || byte == 0x7f) {
            out += "\\x";
            out += hex[byte >> 4];
            out += hex[byte & 0xf];
        } else {
            out += ch;
        }
    }
    return out;
}

} // namespace text
