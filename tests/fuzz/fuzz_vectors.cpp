// libFuzzer target: arbitrary bytes as frustum-vectors' stdin ->
// vectors::run_frustum_vectors (the whole tool but the process streams).
//
// Besides "no crash" (ASan + UBSan, float division by zero included), each
// run is checked against docs/vectors-contract.md and run.hpp:
//   exit 0: stdout is one strict JSON document {"cases": [...]} with one
//           answer per case, each with "id" and "ok" (and "error" when
//           ok is false); nothing on stderr;
//   exit 2: nothing on stdout, one line "frustum-vectors: ..." on stderr;
//   any other status is wrong for an in-memory stream.
#include "vectors/run.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_vectors: contract violation: %s\n  %.2000s\n", what, detail.c_str());
    std::abort();
}

void check_response(const std::string& out) {
    nlohmann::json response;
    try {
        response = nlohmann::json::parse(out); // strict: no NaN, no Infinity
    } catch (const nlohmann::json::exception& e) {
        fail("exit 0 but stdout is not JSON", std::string(e.what()) + "\n  stdout: " + out);
    }
    if (!response.is_object() || response.size() != 1 || !response.contains("cases") ||
        !response["cases"].is_array()) {
        fail("exit 0 but stdout is not {\"cases\": [...]}", out);
    }
    for (const nlohmann::json& c : response["cases"]) {
        if (!c.is_object() || !c.contains("id") || !c["id"].is_string() || !c.contains("ok") ||
            !c["ok"].is_boolean()) {
            fail("an answer lacks a string id or a boolean ok", c.dump());
        }
        if (!c["ok"].get<bool>() && !(c.contains("error") && c["error"].is_string())) {
            fail("ok: false without an error sentence", c.dump());
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::ostringstream out, err;
    const int status = vectors::run_frustum_vectors(in, out, err);
    const std::string o = out.str(), e = err.str();
    if (status == vectors::kExitOk) {
        if (!e.empty()) fail("exit 0 with text on stderr", e);
        check_response(o);
    } else if (status == vectors::kExitBadInput) {
        if (!o.empty()) fail("exit 2 with text on stdout", o);
        // One line even when the place is a key holding "\n"
        // (regressions/vectors/key-with-newline.json).
        if (e.rfind("frustum-vectors: ", 0) != 0 || e.back() != '\n' || e.find('\n') != e.size() - 1) {
            fail("exit 2 without one \"frustum-vectors: ...\" line on stderr", e);
        }
    } else {
        fail("unexpected exit status", std::to_string(status) + "\n  stderr: " + e);
    }
    return 0;
}
