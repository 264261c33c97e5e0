// JSON text for the response: indented objects, with arrays of scalars kept
// on one line (a matrix, a plane, a point), so golden files diff well.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace vectors {

// Shortest text that reads back as the same double (std::to_chars), e.g.
// "0.1", "-2", "1e-07". Precondition for JSON output: value is finite.
std::string number_text(double value);

// The document as text, 2-space indented, ending in a newline. Keys keep
// their insertion order. Precondition: every number is finite (the caller
// turns a non-finite result into an error, JSON has no NaN).
std::string write_json(const nlohmann::ordered_json& value);

} // namespace vectors
