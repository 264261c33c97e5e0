// frustum-vectors: JSON camera descriptions on stdin -> matrices, inverses,
// planes and key points on stdout (contract: docs/vectors-contract.md).
// These functions write only to the streams they are given; main() passes
// std::cin, std::cout and std::cerr.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace vectors {

// Exit statuses.
inline constexpr int kExitOk = 0;       // the document was well-formed (cases may still have ok: false)
inline constexpr int kExitIoError = 1;  // reading the input or writing the output failed
inline constexpr int kExitBadInput = 2; // bad arguments, malformed JSON, unknown key, wrong type, too large

// Inputs larger than this many bytes are refused (exit 2).
inline constexpr std::size_t kMaxInputBytes = std::size_t(64) << 20; // 64 MiB

// The request on `in`, the response on `out` (only when the exit status is
// 0), one "frustum-vectors: <place>: <problem>" line on `err` otherwise.
int run_frustum_vectors(std::istream& in, std::ostream& out, std::ostream& err);

// The command line: no arguments runs the tool, "--help" alone prints
// usage_text() on `out` and exits 0, anything else is exit 2.
int frustum_vectors_cli(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err);

const char* usage_text();

} // namespace vectors
