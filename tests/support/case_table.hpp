// The loop of the table-driven tests: every case of a table checked the
// same way, the case's name captured, the phrases its message must hold.
#pragma once

#include <doctest/doctest.h>

#include <cstddef>
#include <string>
#include <vector>

namespace support {

// CHECKs that every phrase occurs in text, naming the first missing one and
// the text.
void check_phrases(const std::string& text, const std::vector<std::string>& phrases);

// CHECKs, the message captured, that an error message starts with `prefix`,
// is one line when `one_line`, and holds every phrase (check_phrases).
void check_message(const std::string& message, const std::string& prefix, const std::vector<std::string>& phrases,
                   bool one_line);

// CHECKs that `cases` holds at least `min_cases` rows (a table cut short by
// mistake fails), then runs `check` on each with its `input` (the row's
// name) captured.
template <class Case, class Check>
void for_each_case(const std::vector<Case>& cases, std::size_t min_cases, Check check) {
    CHECK(cases.size() >= min_cases);
    for (const Case& c : cases) {
        const std::string input = c.input;
        CAPTURE(input);
        check(c);
    }
}

} // namespace support
