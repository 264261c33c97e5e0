#include "case_table.hpp"

#include <optional>

namespace support {
namespace {

// Every phrase occurs in text; the first missing one otherwise.
std::optional<std::string> missing_phrase(const std::string& text, const std::vector<std::string>& phrases) {
    for (const std::string& phrase : phrases) {
        if (text.find(phrase) == std::string::npos) {
            return phrase;
        }
    }
    return std::nullopt;
}

} // namespace

void check_phrases(const std::string& text, const std::vector<std::string>& phrases) {
    const auto missing = missing_phrase(text, phrases);
    CHECK_MESSAGE(!missing, "missing phrase: ", missing.value_or(""), "\nin: ", text);
}

void check_message(const std::string& message, const std::string& prefix, const std::vector<std::string>& phrases,
                   bool one_line) {
    CAPTURE(message);
    CHECK(message.rfind(prefix, 0) == 0);
    if (one_line) CHECK(message.find('\n') == std::string::npos);
    check_phrases(message, phrases);
}

} // namespace support
