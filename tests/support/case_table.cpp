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
    CHECK_MESSAGE(!missing, "missing phrase: ", missing.value_or(""));
}

} // namespace support
