// The tools' cases (cli_*_test.cpp, budget_cases_test.cpp) compile only when
// CMake passes the tool's path (suite.cmake, one per target that exists): a
// tool that is not built is a skip here, not a silently shorter suite.
#include "../skips.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

namespace {

void check_built(const char* path_or_null, const std::string& tool, const std::string& cases) {
    if (path_or_null == nullptr) {
        test_skips::skip(tool + " is not built, so " + cases + " did not run");
        return;
    }
    CHECK_MESSAGE(std::filesystem::exists(path_or_null), path_or_null);
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("every command-line tool the suite runs is built, so its cases ran") {
#ifdef FRUSTUM_DEMO_EXE
    check_built(FRUSTUM_DEMO_EXE, "frustum-demo", "cli_demo_test.cpp and budget_cases_test.cpp");
#else
    check_built(nullptr, "frustum-demo", "cli_demo_test.cpp and budget_cases_test.cpp");
#endif
#ifdef FRUSTUM_EXPLAIN_EXE
    check_built(FRUSTUM_EXPLAIN_EXE, "frustum-explain", "cli_explain_test.cpp");
#else
    check_built(nullptr, "frustum-explain", "cli_explain_test.cpp");
#endif
#ifdef FRUSTUM_VECTORS_EXE
    check_built(FRUSTUM_VECTORS_EXE, "frustum-vectors", "cli_vectors_test.cpp and budget_cases_test.cpp's vectors case");
#else
    check_built(nullptr, "frustum-vectors", "cli_vectors_test.cpp and budget_cases_test.cpp's vectors case");
#endif
}

} // TEST_SUITE
