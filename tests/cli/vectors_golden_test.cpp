// Golden vectors (tests/golden/): the checked-in response must be what the
// tool answers today, within 1e-9 relative (per array: relative to its
// largest entry) + 1e-12 absolute, so a silent change in the library fails
// here. After a deliberate change: scripts/regen-golden.sh, then review the diff.
#include "vectors_checks.hpp"

#include "vectors/json_reader.hpp"

#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>

using namespace vectors_test;

namespace {

constexpr double kRelative = 1e-9;
constexpr double kAbsolute = 1e-12;

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot open " << path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string golden(const char* name) { return read_file(std::string(FRUSTUM_SOURCE_DIR) + "/tests/golden/" + name); }

double largest_number(const json& array) {
    double largest = 0;
    for (const json& v : array) {
        if (v.is_number()) {
            largest = std::max(largest, std::abs(v.get<double>()));
        }
    }
    return largest;
}

// How far the tool's numbers are from the checked-in ones (made on
// x86-64): printed by every golden case, so a cross build (make test-arm,
// docs/porting.md) reports its drift even when it holds the tolerance.
struct Drift {
    int numbers = 0;     // numbers compared
    int different = 0;   // not bit-identical
    double worst = 0;    // largest |expected - actual| / max(scale, |expected|)
};

// An error text's numbers (far_corner_side=-1.0499999999997272) are the
// library's doubles printed shortest-round-trip, so they drift like the
// numbers around them: the text outside the numbers must be equal, each
// number within the tolerance (kRelative of its own size).
void compare_text(const std::string& expected, const std::string& actual, Drift& drift) {
    static const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
    const auto skeleton = [](const std::string& text) { return std::regex_replace(text, number, "#"); };
    REQUIRE(skeleton(expected) == skeleton(actual));
    std::sregex_iterator e(expected.begin(), expected.end(), number), a(actual.begin(), actual.end(), number), end;
    for (; e != end && a != end; ++e, ++a) {
        const double x = std::stod(e->str()), y = std::stod(a->str());
        INFO("in \"" << expected << "\": expected " << e->str() << ", got " << a->str());
        CHECK(std::abs(x - y) <= kRelative * std::abs(x) + kAbsolute);
        ++drift.numbers;
        if (x != y) {
            ++drift.different;
            drift.worst = std::max(drift.worst, x != 0 ? std::abs(x - y) / std::abs(x) : std::abs(x - y));
        }
    }
}

// Same structure, same strings and booleans, numbers within tolerance.
// `scale` is the largest magnitude of the array holding the number.
void compare(const json& expected, const json& actual, const std::string& path, Drift& drift, double scale = 0) {
    INFO("at " << path);
    if (expected.is_number() && actual.is_number()) {
        const double e = expected.get<double>(), a = actual.get<double>();
        INFO("expected " << e << ", got " << a);
        CHECK(std::abs(e - a) <= kRelative * std::max(scale, std::abs(e)) + kAbsolute);
        ++drift.numbers;
        if (e != a) {
            ++drift.different;
            const double size = std::max(scale, std::abs(e));
            drift.worst = std::max(drift.worst, size > 0 ? std::abs(e - a) / size : std::abs(e - a));
        }
        return;
    }
    REQUIRE(expected.type_name() == std::string(actual.type_name()));
    if (expected.is_object()) {
        REQUIRE(expected.size() == actual.size());
        for (const auto& item : expected.items()) {
            REQUIRE_MESSAGE(actual.contains(item.key()), "missing key " << item.key());
            compare(item.value(), actual[item.key()], path + "." + item.key(), drift);
        }
    } else if (expected.is_array()) {
        REQUIRE(expected.size() == actual.size());
        const double array_scale = largest_number(expected);
        for (std::size_t i = 0; i < expected.size(); ++i) {
            compare(expected[i], actual[i], path + "[" + std::to_string(i) + "]", drift, array_scale);
        }
    } else if (expected.is_string()) {
        compare_text(expected.get<std::string>(), actual.get<std::string>(), drift); // id, error
    } else {
        CHECK(expected == actual); // booleans, null
    }
}

// The tool's answer to tests/golden/<request> against tests/golden/<response>.
void check_golden(const char* request, const char* response) {
    const Run r = run_text(golden(request));
    REQUIRE_MESSAGE(r.status == 0, r.err);
    const json expected = json::parse(golden(response));
    const json actual = json::parse(r.out);
    REQUIRE(expected["cases"].size() == actual["cases"].size());
    Drift drift;
    for (std::size_t i = 0; i < expected["cases"].size(); ++i) {
        const json& e = expected["cases"][i];
        compare(e, actual["cases"][i], "cases[" + std::to_string(i) + "] (" + e["id"].get<std::string>() + ")", drift);
    }
    MESSAGE("golden drift " << std::string(response) << ": " << drift.different << " of " << drift.numbers
                            << " numbers differ, worst relative difference " << drift.worst);
}

} // namespace

TEST_SUITE("cli") {

TEST_CASE("vectors golden: the tool still answers request-v1.json with response-v1.json") {
    check_golden("request-v1.json", "response-v1.json");
}

TEST_CASE("vectors golden: the tool still answers request-v2.json with response-v2.json") {
    check_golden("request-v2.json", "response-v2.json");
}

// The request holds 1e999, which nlohmann::json::parse refuses; the tool's
// own reader turns it into infinity.
json golden_request(const char* name = "request-v1.json") {
    const auto request = vectors::read_json(golden(name));
    REQUIRE_MESSAGE(request.ok(), request.error());
    return *request;
}

// Every ok answer of tests/golden/<response> against its request through
// check_consistent (glm::inverse, the plane rows, unprojected corners), not
// against the tool's own output. Returns how many answers were checked.
int check_golden_consistent(const char* request, const char* response_name) {
    const json cases = golden_request(request)["cases"];
    const json response = json::parse(golden(response_name))["cases"];
    REQUIRE(cases.size() == response.size());
    int checked = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        REQUIRE(cases[i]["id"] == response[i]["id"]);
        if (response[i]["ok"].get<bool>()) {
            check_consistent(cases[i], response[i]);
            ++checked;
        }
    }
    return checked;
}

TEST_CASE("vectors golden: every ok answer of the checked-in response is self-consistent") {
    CHECK(check_golden_consistent("request-v1.json", "response-v1.json") >= 40); // 56 of its 88 cases are ok
}

TEST_CASE("vectors golden: every ok answer of response-v2.json is self-consistent too") {
    CHECK(check_golden_consistent("request-v2.json", "response-v2.json") >= 25); // 31 of its 43 cases are ok
}

TEST_CASE("vectors golden: request-v1.json covers every camera, op, depth range and failure kind") {
    const json cases = golden_request()["cases"];
    const json response = json::parse(golden("response-v1.json"))["cases"];
    REQUIRE(cases.size() == response.size());
    std::set<std::string> cameras, ops, depths, ids;
    int infinite_far = 0, with_points = 0, failures = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const json& c = cases[i];
        CHECK(ids.insert(c["id"].get<std::string>()).second); // ids are unique
        cameras.insert(c["camera"].begin().key());
        depths.insert(c.value("depth", std::string("zero_to_one")));
        for (const json& op : c.value("ops", json::array())) {
            ops.insert(op.begin().key());
        }
        infinite_far += response[i]["ok"].get<bool>() && response[i]["planes"]["far"].is_null();
        with_points += c.contains("points") && !c["points"].empty();
        failures += !response[i]["ok"].get<bool>();
    }
    int overflow = 0; // "1e999" in the text: read as infinity, an ok: false case
    const std::string raw = golden("request-v1.json");
    for (std::size_t at = raw.find("1e999"); at != std::string::npos; at = raw.find("1e999", at + 1)) {
        ++overflow;
    }
    CHECK(cameras == std::set<std::string>{"perspective", "frustum", "ortho", "planes", "mirror_rect", "matrix"});
    CHECK(ops == std::set<std::string>{"crop", "reflect", "clip", "mirror"});
    CHECK(depths == std::set<std::string>{"zero_to_one", "minus_one_to_one", "reversed_zero_to_one"});
    CHECK(infinite_far >= 6);
    CHECK(with_points >= 20);
    CHECK(failures >= 20);
    CHECK(overflow >= 3);
}

TEST_CASE("vectors golden: request-v2.json covers portal, jitter, screen_rects, cull and their failures") {
    const json cases = golden_request("request-v2.json")["cases"];
    const json response = json::parse(golden("response-v2.json"))["cases"];
    REQUIRE(cases.size() == response.size());
    std::set<std::string> ops, depths, ids;
    int rects = 0, null_rects = 0, failures = 0;
    std::set<std::string> cull_words;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const json& c = cases[i];
        const json& a = response[i];
        CHECK(ids.insert(c["id"].get<std::string>()).second);
        depths.insert(c.value("depth", std::string("zero_to_one")));
        for (const json& op : c.value("ops", json::array())) {
            ops.insert(op.begin().key());
        }
        if (!a["ok"].get<bool>()) {
            ++failures;
            CHECK(c["id"].get<std::string>().rfind("bad-", 0) == 0);
            continue;
        }
        CHECK(c.contains("rects") == a.contains("screen_rects"));
        CHECK(c.contains("boxes") == a.contains("cull"));
        if (c.contains("rects")) {
            REQUIRE(a["screen_rects"].size() == c["rects"].size());
            for (const json& r : a["screen_rects"]) {
                ++rects;
                null_rects += r.is_null();
            }
        }
        if (c.contains("boxes")) {
            REQUIRE(a["cull"].size() == c["boxes"].size());
            for (const json& w : a["cull"]) cull_words.insert(w.get<std::string>());
        }
    }
    CHECK(ops.count("portal") == 1);
    CHECK(ops.count("jitter") == 1);
    CHECK(depths == std::set<std::string>{"zero_to_one", "minus_one_to_one", "reversed_zero_to_one"});
    CHECK(cull_words == std::set<std::string>{"outside", "intersect", "inside"});
    CHECK(rects >= 10);
    CHECK(null_rects >= 3);
    CHECK(failures >= 10);
}

TEST_CASE("vectors golden: version 1 files are untouched by version 2 (no v2 key in them)") {
    const std::string request = golden("request-v1.json"), response = golden("response-v1.json");
    for (const char* key : {"\"portal\"", "\"jitter\"", "\"rects\"", "\"boxes\"", "\"screen_rects\"", "\"cull\""}) {
        CHECK(request.find(key) == std::string::npos);
        CHECK(response.find(key) == std::string::npos);
    }
}

TEST_CASE("vectors golden: every input of malformed-v1.json is exit 2, naming its place") {
    const json file = json::parse(golden("malformed-v1.json"));
    CHECK(file["version"] == 1);
    REQUIRE(file["inputs"].size() >= 20);
    for (const json& item : file["inputs"]) {
        INFO(item["name"].get<std::string>());
        const std::string err = rejected(item["input"].get<std::string>());
        CHECK(err.find(item["place"].get<std::string>()) != std::string::npos);
    }
}

} // TEST_SUITE
