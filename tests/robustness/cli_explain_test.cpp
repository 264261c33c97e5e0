// frustum-explain as a built binary: a bad option or value is exit 2 with a
// message naming it; a camera the library refuses is exit 1 with the
// library's message; nothing goes to stdout in either case.
#ifdef FRUSTUM_EXPLAIN_EXE
#include "support.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace {

struct ExplainCase {
    const char* input;
    std::vector<std::string> args;
    int exit_status;
    std::vector<std::string> phrases; // on stderr
};

const std::vector<ExplainCase>& explain_cases() {
    static const std::vector<ExplainCase> cases = {
        {"unknown option", {"--fov", "60"}, 2, {"frustum-explain: unknown option '--fov'", "usage:"}},
        {"missing value", {"--near"}, 2, {"frustum-explain: --near expects a number, got 'nothing'"}},
        {"value not a number", {"--aspect", "wide"}, 2, {"--aspect expects a number, got 'wide'"}},
        {"value with trailing text", {"--far", "100m"}, 2, {"--far expects a number, got '100m'"}},
        {"near -1", {"--near", "-1"}, 1, {"frustum-explain: frustum::perspective(): near must be > 0", "near=-1"}},
        {"far <= near", {"--near", "5", "--far", "5"}, 1, {"frustum-explain: ", "far must be finite and > near"}},
        {"fovy 180 degrees", {"--fovy-deg", "180"}, 1, {"frustum-explain: ", "fovy_rad must be in (0, pi)"}},
        {"aspect 0", {"--aspect", "0"}, 1, {"frustum-explain: ", "aspect must be > 0"}},
        {"near NaN", {"--near", "nan"}, 1, {"frustum-explain: ", "near must be > 0 and finite"}},
        {"fovy 1e999", {"--fovy-deg", "1e999"}, 1, {"frustum-explain: ", "fovy_rad must be in (0, pi)"}},
    };
    return cases;
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("frustum-explain: bad options and cameras") {
    support::for_each_case(explain_cases(), 8, [](const ExplainCase& c) {
        const support::Outcome r = rob::run_checked(FRUSTUM_EXPLAIN_EXE, c.args, c.exit_status, true);
        support::check_phrases(r.err, c.phrases);
    });
}

} // TEST_SUITE
#endif
