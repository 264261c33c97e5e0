// frustum-vectors output format and command line: key order, column-major
// layout, round-tripping numbers, the id echo, --help, limits, exit codes.
#include "vectors_support.hpp"

#include <frustum/projection.hpp>
#include <frustum/queries.hpp>

#include <cmath>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

using namespace vectors_test;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::string> keys(const nlohmann::ordered_json& object) {
    std::vector<std::string> out;
    for (const auto& item : object.items()) {
        out.push_back(item.key());
    }
    return out;
}

Run cli(const std::vector<std::string>& args, const std::string& input) {
    std::istringstream in(input);
    std::ostringstream out, err;
    Run r;
    r.status = vectors::frustum_vectors_cli(args, in, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

// A stream buffer that refuses every write (a closed or full stdout).
struct FailingBuffer : std::streambuf {
    int overflow(int) override { return traits_type::eof(); }
    std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
};

} // namespace

TEST_SUITE("cli") {

TEST_CASE("vectors: keys come in the contract's order") {
    const Run r = run_text(R"({"cases": [
        {"id": "a", "camera": {"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": 0.1, "far": null}},
         "points": [[0, 0, -1]]},
        {"id": "b", "camera": {"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": 0.1, "far": 100}}},
        {"id": "c", "camera": {"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": -0.1, "far": 100}}}]})");
    REQUIRE(r.status == 0);
    const auto response = nlohmann::ordered_json::parse(r.out);
    CHECK(keys(response) == std::vector<std::string>{"cases"});
    const auto& a = response["cases"][0];
    CHECK(keys(a) == std::vector<std::string>{"id", "ok", "matrix", "inverse", "planes", "corners", "center", "vanishing",
                                              "valid", "clip", "inside"});
    CHECK(keys(a["planes"]) == std::vector<std::string>{"left", "right", "bottom", "top", "near", "far"});
    CHECK(a["planes"]["far"].is_null());
    CHECK(keys(a["vanishing"]) == std::vector<std::string>{"O", "O1", "O2"});
    CHECK(a["corners"].size() == 8);
    const auto& b = response["cases"][1];
    CHECK(keys(b) == std::vector<std::string>{"id", "ok", "matrix", "inverse", "planes", "corners", "center", "vanishing",
                                              "valid"});
    const auto& c = response["cases"][2];
    CHECK(keys(c) == std::vector<std::string>{"id", "ok", "error"});
    CHECK(c["ok"] == false);
}

TEST_CASE("vectors: matrices are column-major and every number round-trips the library's double") {
    const json a = answer({{"id", "p"},
                           {"depth", "minus_one_to_one"},
                           {"camera", {{"perspective", {{"fovy_deg", 50}, {"aspect", 1.25}, {"near", 0.3}, {"far", 70}}}}},
                           {"view", {{"eye", {1, 2, 3}}, {"target", {0.1, 0.2, -0.3}}, {"up", {0, 1, 0}}}}});
    const auto projection = frustum::perspective<double>(50 * kPi / 180, 1.25, 0.3, 70.0, frustum::DepthRange::MinusOneToOne);
    const auto view = frustum::look_at<double>({1, 2, 3}, {0.1, 0.2, -0.3}, {0, 1, 0});
    REQUIRE(projection.ok());
    REQUIRE(view.ok());
    const auto pair = frustum::compose(*projection, *view);
    // Bit for bit: the text of each number reads back as the same double.
    CHECK(mat4(a["matrix"]) == pair.matrix());
    CHECK(mat4(a["inverse"]) == pair.inverse());
    const auto points = frustum::key_points(pair);
    for (int i = 0; i < 8; ++i) {
        CHECK(vec4(a["corners"][static_cast<std::size_t>(i)]) ==
              frustum::to_point(points.corners[static_cast<std::size_t>(i)], 1e-12));
    }

    // Column-major: a projection has m[2][3] = -1 (clip w = -z_eye) at index 11.
    const json p = answer({{"id", "p"}, {"camera", {{"perspective", {{"fovy_deg", 90}, {"aspect", 1}, {"near", 1}, {"far", 3}}}}}});
    CHECK(p["matrix"][11] == -1.0);
    CHECK(p["matrix"][14] == -1.5); // m[3][2] = -n f / (f - n) for [0, 1]
    CHECK(p["matrix"][15] == 0.0);
}

TEST_CASE("vectors: the output text is JSON with shortest round-trip numbers, one case per block") {
    const Run r = run_text(R"({"cases": [{"id": "a", "camera": {"ortho": {"left": -1, "right": 1, "bottom": -1,
                              "top": 1, "near": 0, "far": 10}}, "points": []}]})");
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\"matrix\": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.1, 0, -0, -0, 0, 1],") != std::string::npos);
    CHECK(r.out.find("\"clip\": [],") != std::string::npos);
    CHECK(r.out.find("\"inside\": []") != std::string::npos);
    CHECK(r.out.find("nan") == std::string::npos);
    CHECK(r.out.find("inf") == std::string::npos);
    CHECK(r.out.back() == '\n');
    CHECK(run_text(R"({"cases": []})").out == "{\n  \"cases\": []\n}\n");
}

TEST_CASE("vectors: ids are echoed verbatim, escapes and UTF-8 included") {
    const std::string id = "tab\t \"quoted\" back\\slash \xC3\xA9 \xF0\x9F\x98\x80 \x01";
    json request = {{"cases", {{{"id", id}, {"camera", {{"ortho", {{"left", -1}, {"right", 1}, {"bottom", -1}, {"top", 1},
                                                                   {"near", 0}, {"far", 1}}}}}}}}};
    const json response = run_ok(request);
    CHECK(response["cases"][0]["id"] == id);
    // \u escapes, surrogate pairs included, decode to the same text.
    const Run r = run_text(R"({"cases": [{"id": "\u00e9\ud83d\ude00\/", "camera": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}}]})");
    REQUIRE(r.status == 0);
    CHECK(json::parse(r.out)["cases"][0]["id"] == "\xC3\xA9\xF0\x9F\x98\x80/");
}

TEST_CASE("vectors: JSON numbers: integers, exponents, huge and tiny values") {
    // 6e1 = 60 degrees, 15E-1 = 1.5, 1e-400 underflows to 0 (an ortho near of 0 is fine).
    const json a = answer(json::parse(R"({"id": "n", "camera": {"perspective": {"fovy_deg": 6e1, "aspect": 15E-1,
        "near": 0.1, "far": 1e2}}})"));
    const json b = answer(json::parse(R"({"id": "n", "camera": {"perspective": {"fovy_deg": 60, "aspect": 1.5,
        "near": 0.1, "far": 100}}})"));
    CHECK(a["matrix"] == b["matrix"]);
    const Run r = run_text(R"({"cases": [{"id": "z", "camera": {"ortho": {"left": -1, "right": 1, "bottom": -1, "top": 1,
        "near": -1e-400, "far": 1}}}, {"id": "big", "camera": {"ortho": {"left": -1, "right": 1, "bottom": -1, "top": 1,
        "near": 0, "far": 123456789012345678901234567890}}}]})");
    REQUIRE(r.status == 0);
    const json response = json::parse(r.out);
    CHECK(response["cases"][0]["ok"] == true);
    CHECK(response["cases"][1]["ok"] == true);
}

TEST_CASE("vectors: --help prints usage and exits 0; other arguments are exit 2") {
    const Run help = cli({"--help"}, "");
    CHECK(help.status == 0);
    CHECK(help.out.rfind("usage: frustum-vectors", 0) == 0);
    CHECK(help.out.find("Exit status") != std::string::npos);
    CHECK(help.err.empty());
    // Each refusal names the first argument, the one that cannot be taken.
    const std::vector<std::pair<std::vector<std::string>, std::string>> refused = {
        {{"-h"}, "-h"}, {{"--help", "x"}, "--help"}, {{"request.json"}, "request.json"}, {{""}, ""}};
    for (const auto& row : refused) {
        const std::vector<std::string>& args = row.first;
        const std::string& named = row.second; // not a structured binding: CAPTURE's lambda takes it (clang, C++17)
        CAPTURE(named);
        const Run r = cli(args, R"({"cases": []})");
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err == "frustum-vectors: unexpected argument \"" + named +
                           "\" (the request is read from standard input; see --help)\n");
    }
    const Run plain = cli({}, R"({"cases": []})");
    CHECK(plain.status == 0);
    CHECK(plain.out == "{\n  \"cases\": []\n}\n");
}

TEST_CASE("vectors: inputs over 64 MiB are refused") {
    std::string text = R"({"cases": []})";
    text.resize(vectors::kMaxInputBytes, ' '); // exactly 64 MiB: accepted
    CHECK(run_text(text).status == 0);
    text.push_back(' ');
    const Run r = run_text(text);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "frustum-vectors: input is larger than 64 MiB (67108864 bytes)\n");
}

TEST_CASE("vectors: a failing output stream is exit 1") {
    FailingBuffer buffer;
    std::ostream out(&buffer);
    std::istringstream in(R"({"cases": []})");
    std::ostringstream err;
    CHECK(vectors::run_frustum_vectors(in, out, err) == 1);
    CHECK(err.str() == "frustum-vectors: cannot write the output\n");
}

} // TEST_SUITE
