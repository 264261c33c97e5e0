// A strict JSON reader (RFC 8259) for frustum-vectors requests.
//
// Why not nlohmann::json::parse: it rejects a number that overflows a double
// ("1e999") as a parse error, but the vectors contract says such a number is
// infinity, a geometric error of its case (ok: false), not a malformed
// document. This reader builds the same nlohmann::json tree and differs only
// where the contract needs it:
//   - a number too large for a double becomes +-infinity, one too small +-0;
//   - a key repeated in one object is an error (nlohmann keeps the last one
//     silently, which would hide a typo in a golden file);
//   - nesting is limited to kMaxJsonDepth (no stack overflow on "[[[[...");
//   - at most kMaxJsonValues values (the tree costs ~100 B per value, so a
//     64 MiB document of "{}" would otherwise build a 2 GB tree);
//   - strings must be valid UTF-8 (the id is echoed back verbatim).
// Everything else (NaN, Infinity, comments, trailing commas, a BOM, leading
// zeros, single quotes) is malformed, as in RFC 8259.
#pragma once

#include <frustum/result.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string_view>

namespace vectors {

constexpr int kMaxJsonDepth = 64;
constexpr std::size_t kMaxJsonValues = 1000000;

// Errors read "invalid JSON at line 3, column 7: expected ',' or '}'"
// (lines and columns count from 1; columns in bytes).
frustum::Result<nlohmann::json> read_json(std::string_view text);

} // namespace vectors
