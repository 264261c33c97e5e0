// Running frustum-demo as a child process for the window suite: the suite's
// timeout over tests/support's runner, with environment variables removed
// or set.
#pragma once

#include "support/child_process.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace window_test {

// exit_status, out and err of a finished child (tests/support).
using Child = support::Outcome;

// The longest a child may run: the longest measured, the key sweep under
// xvfb-run (about 40 s alone on llvmpipe, 2 cores), times 7 for a loaded
// machine. A hung child (an X server that never comes up, a window that
// never closes) then fails its test instead of stalling the suite.
inline constexpr int kChildTimeoutS = 300;

// support::run() of `program` with `args`, at most `timeout_s`.
// `environment`: a value sets the variable, nullopt removes it; the rest is
// inherited.
Child run(const std::string& program, const std::vector<std::string>& args,
          const std::map<std::string, std::optional<std::string>>& environment = {},
          int timeout_s = kChildTimeoutS);

// `name` found on PATH, else empty (tests/support).
using support::find_on_path;

} // namespace window_test
