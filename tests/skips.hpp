// A check that cannot run here (no GL context, one backend missing, a tool
// not installed) is reported as a skip, never as a pass. skip() prints the
// reason and records it; the suite's main (skips_main.hpp) then exits with
// kSkipExitCode, CTest's SKIP_RETURN_CODE for every suite, unless a check
// failed. With FRUSTUM_REQUIRE_ALL=1 (CI, where both backends and the window
// tools are installed) a skip is a failure instead.
#pragma once

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace test_skips {

inline constexpr int kSkipExitCode = 77;

inline bool all_required() {
    const char* value = std::getenv("FRUSTUM_REQUIRE_ALL");
    return value != nullptr && std::string(value) == "1";
}

// "test case: reason" of every skip of this run.
inline std::vector<std::string>& skipped() {
    static std::vector<std::string> list;
    return list;
}

// The running test case's name (set by skips_main.hpp's listener).
inline std::string& current_test_case() {
    static std::string name;
    return name;
}

// Call, then return from the test case (or skip the loop iteration) without the checks that need what is missing.
inline void skip(const std::string& reason) {
    if (all_required()) {
        FAIL_CHECK("FRUSTUM_REQUIRE_ALL=1, so this is a failure, not a skip: " << reason);
        return;
    }
    MESSAGE("SKIPPED: " << reason);
    skipped().push_back(current_test_case() + ": " + reason);
}

} // namespace test_skips
