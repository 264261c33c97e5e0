#include "json_depth.hpp"

#include <string>

namespace scene::detail {

frustum::Status check_json_depth(const char* text, std::size_t size_bytes, int max_depth) {
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < size_bytes; ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') {
                ++i; // skip the escaped character
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > max_depth) {
                return frustum::Error{"JSON nesting depth exceeds " + std::to_string(max_depth) +
                                      " at byte " + std::to_string(i)};
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return {};
}

} // namespace scene::detail
