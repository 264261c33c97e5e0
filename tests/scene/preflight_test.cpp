// The byte-level checks that run before any JSON parser: uri rules and the
// JSON nesting bound.
#include "scene/json_depth.hpp"
#include "scene/uri_check.hpp"

#include <doctest/doctest.h>

#include <string>

namespace {

bool depth_ok(const std::string& json, int max_depth) {
    return scene::detail::check_json_depth(json.data(), json.size(), max_depth).ok();
}

} // namespace

TEST_SUITE("scene") {

TEST_CASE("uri rules") {
    using scene::detail::uri_problem;
    for (const char* good : {"a.bin", "./a.bin", "sub/a.bin", "sub/./a.bin", "a%20b.bin", "..a.bin",
                             "a..bin", "data:application/octet-stream;base64,AAAA"}) {
        CAPTURE(good);
        CHECK(uri_problem(good).empty());
    }
    struct Bad {
        const char* uri;
        const char* phrase;
    };
    for (const Bad& bad : {Bad{"", "is empty"}, Bad{".", "names a folder"}, Bad{"sub/", "names a folder"},
                           Bad{"sub/.", "names a folder"}, Bad{"..", "\"..\""}, Bad{"../a.bin", "\"..\""},
                           Bad{"a/../../b.bin", "\"..\""}, Bad{"%2E%2E/a.bin", "\"..\""},
                           Bad{"/etc/passwd", "absolute"}, Bad{"%2Fetc/passwd", "absolute"},
                           Bad{"http://example.com/a.bin", "scheme"}, Bad{"C:\\a.bin", "backslash"},
                           Bad{"a%00.bin", "NUL"}, Bad{"data:application/octet-stream,AAAA", "base64"}}) {
        CAPTURE(bad.uri);
        CHECK(uri_problem(bad.uri).find(bad.phrase) != std::string::npos);
    }
}

TEST_CASE("JSON nesting bound ignores brackets inside strings") {
    CHECK(depth_ok("{\"a\": [[1]]}", 3));
    CHECK_FALSE(depth_ok("{\"a\": [[[1]]]}", 3));
    CHECK(depth_ok("{\"a\": \"[[[[[[\"}", 1));
    CHECK(depth_ok("{\"a\": \"\\\"[[[[[[\"}", 1)); // escaped quote stays inside the string
    CHECK_FALSE(depth_ok("{\"a\\\\\": [[1]]}", 2)); // escaped backslash ends before the quote
    CHECK(depth_ok(std::string(64, '[') + std::string(64, ']'), 64));
    CHECK_FALSE(depth_ok(std::string(65, '[') + std::string(65, ']'), 64));
}

} // TEST_SUITE
