#include "foreign_message.hpp"

namespace scene::detail {

namespace {

constexpr std::size_t kMaxWordBytes = 80;
constexpr std::size_t kClippedWordBytes = 60;

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

} // namespace

std::string foreign_message(const std::string& text) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        if (is_space(text[i])) {
            const bool line_break = text[i] == '\n';
            while (i < text.size() && is_space(text[i])) ++i;
            if (i < text.size()) out += line_break ? "; " : " ";
            continue;
        }
        std::size_t end = i;
        while (end < text.size() && !is_space(text[end])) ++end;
        const std::size_t length = end - i;
        if (length > kMaxWordBytes) {
            out += text.substr(i, kClippedWordBytes) + "...(" + std::to_string(length) + " bytes)";
        } else {
            out += text.substr(i, length);
        }
        i = end;
    }
    return out;
}

} // namespace scene::detail
