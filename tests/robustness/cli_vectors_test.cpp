// frustum-vectors as a built binary (docs/vectors-contract.md): bad arguments
// and malformed requests exit 2 with one "frustum-vectors: <place>: ..." line
// on stderr and NOTHING on stdout; a failed write exits 1; well-formed but
// impossible cases exit 0 with "ok": false.
#ifdef FRUSTUM_VECTORS_EXE
#include "support.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace {

struct VectorsCase {
    const char* input;
    std::vector<std::string> args;
    std::string stdin_text;
    int exit_status;
    std::vector<std::string> phrases; // on stderr when exit != 0, else on stdout
};

std::string one_case(const std::string& camera) {
    return R"({"cases": [{"id": "c", "camera": )" + camera + "}]}";
}
const std::string kPerspective = R"({"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": 0.1, "far": 100}})";

const std::vector<VectorsCase>& vectors_cases() {
    static const std::vector<VectorsCase> cases = {
        {"unknown argument", {"--bogus"}, one_case(kPerspective), 2, {"frustum-vectors: ", "--bogus"}},
        {"--help with an extra argument", {"--help", "x"}, "", 2, {"frustum-vectors: "}},
        {"empty stdin", {}, "", 2, {"frustum-vectors: invalid JSON at line 1, column 1: the input is empty"}},
        {"truncated JSON", {}, R"({"cases": [{"id": )", 2, {"frustum-vectors: invalid JSON at line 1"}},
        {"binary garbage", {}, std::string("\x00\xff\xfe{", 4), 2, {"frustum-vectors: invalid JSON at line 1, column 1"}},
        {"NaN literal", {}, one_case(R"({"perspective": {"fovy_deg": NaN, "aspect": 1, "near": 1, "far": 2}})"), 2,
         {"frustum-vectors: invalid JSON"}},
        {"unknown key", {}, R"({"cases": [], "extra": 1})", 2, {"frustum-vectors: extra: unknown key"}},
        {"wrong type", {}, one_case(R"({"perspective": {"fovy_deg": "60", "aspect": 1, "near": 1, "far": 2}})"), 2,
         {"frustum-vectors: cases[0].camera.perspective.fovy_deg: expected a number"}},
        {"two camera kinds", {}, one_case(R"({"perspective": {}, "ortho": {}})"), 2,
         {"frustum-vectors: cases[0].camera"}},
        // The message must stay one line even when the place is a key holding "\n".
        {"unknown key holding a newline", {}, "{\"cases\": [], \"x\\ny\": 1}", 2, {"frustum-vectors: ", "unknown key"}},
        {"deep nesting", {}, std::string(100000, '[') + std::string(100000, ']'), 2,
         {"frustum-vectors: ", "nest deeper than 64 levels"}},
        {"near -1 (impossible, exit 0)", {},
         one_case(R"({"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": -1, "far": 100}})"), 0,
         {"\"ok\": false", "near must be > 0"}},
        {"aspect 0 (impossible, exit 0)", {},
         one_case(R"({"perspective": {"fovy_deg": 60, "aspect": 0, "near": 0.1, "far": 100}})"), 0,
         {"\"ok\": false", "aspect must be > 0"}},
        {"1e999 (infinity, exit 0)", {},
         one_case(R"({"perspective": {"fovy_deg": 1e999, "aspect": 1.5, "near": 0.1, "far": 100}})"), 0,
         {"\"ok\": false"}},
        {"singular matrix (exit 0)", {}, one_case(R"({"matrix": [0,0,0,0, 0,0,0,0, 0,0,0,0, 0,0,0,0]})"), 0,
         {"\"ok\": false", "singular"}},
    };
    return cases;
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("frustum-vectors: bad arguments and requests") {
    support::for_each_case(vectors_cases(), 12, [](const VectorsCase& c) {
        const support::Outcome r =
            rob::run_checked(FRUSTUM_VECTORS_EXE, c.args, c.exit_status, c.exit_status != 0, c.stdin_text);
        CAPTURE(r.err);
        if (c.exit_status != 0) {
            CHECK(r.err.rfind("frustum-vectors: ", 0) == 0);
            CHECK(r.err.find('\n') == r.err.size() - 1); // one line
        } else {
            CHECK(r.err.empty());
        }
        support::check_phrases(c.exit_status != 0 ? r.err : r.out, c.phrases);
    });
}

TEST_CASE("frustum-vectors: input over 64 MiB is exit 2 with nothing on stdout") {
    support::TempDir dir;
    const std::string big = (dir / "big.json").string();
    const int fd = ::open(big.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    REQUIRE(fd >= 0);
    REQUIRE(::ftruncate(fd, (off_t(64) << 20) + 1) == 0); // sparse: zero bytes
    ::close(fd);
    support::Launch launch;
    launch.stdin_file = big;
    const support::Outcome r = support::run(FRUSTUM_VECTORS_EXE, launch);
    CHECK(r.exit_status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("frustum-vectors: input is larger than 64 MiB") == 0);
}

TEST_CASE("frustum-vectors: a failed write of stdout is exit 1") {
    support::Launch launch;
    launch.stdin_text = one_case(kPerspective);
    launch.stdout_file = "/dev/full";
    const support::Outcome r = support::run(FRUSTUM_VECTORS_EXE, launch);
    CAPTURE(r.err);
    CHECK(r.exit_status == 1);
    CHECK(r.err == "frustum-vectors: cannot write the output\n");
}

} // TEST_SUITE
#endif
