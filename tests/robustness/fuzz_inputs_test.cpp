// Replays the fuzzers' inputs through the same entry points in the normal
// build: the seed corpora (tests/fuzz/corpus) and every crash reproducer
// (tests/fuzz/regressions), each in a child process so that one crash does
// not stop the others. A reproducer must now end in a clean error: a
// glTF file is refused with a one-line message, a frustum-vectors request
// gets exit 0 with a JSON answer or exit 2 with one stderr line and no stdout.
#include "support.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> files_in(const fs::path& dir) {
    std::vector<fs::path> files;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(dir, error)) {
        if (entry.is_regular_file() && entry.path().filename().string()[0] != '.') files.push_back(entry.path());
    }
    return files;
}

std::string read_bytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
}

const fs::path kFuzz = FRUSTUM_FUZZ_DIR;

} // namespace

#if __has_include("scene/load_gltf.hpp")
#include "gltf_layout.hpp"
#include "scene/load_gltf.hpp"

namespace {

// Loads the bytes as fuzz_gltf does; returns the error ("" when loaded).
std::string load_like_fuzz_gltf(const std::string& bytes) {
    support::TempDir dir;
    const std::string model = fuzz_layout::make(dir.path());
    REQUIRE_FALSE(model.empty());
    support::write_file(model, bytes);
    const rob::Isolated load = rob::isolated([&model] {
        const auto result = scene::load_gltf(model);
        return result.ok() ? std::string("loaded") : "error: " + result.error();
    });
    REQUIRE_MESSAGE(load.finished, "load_gltf() did not return: ", load.how);
    if (load.value == "loaded") return "";
    const std::string message = load.value.substr(7);
    CHECK(message.rfind("scene::load_gltf(): " + model + ": ", 0) == 0);
    CHECK(message.find('\n') == std::string::npos);
    return message;
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("fuzz inputs: the glTF seeds load or fail cleanly") {
    // The seeds scripts/fuzz.sh starts from: tests/fuzz/corpus/gltf (hostile
    // ones and the generated mirror-lens box), every generated model
    // (tests/data/gltf-models) and the showcase.
    auto seeds = files_in(kFuzz / "corpus" / "gltf");
    CHECK(seeds.size() >= 16);
    const fs::path source(FRUSTUM_SOURCE_DIR);
    for (const fs::path& model : files_in(source / "tests" / "data" / "gltf-models")) {
        if (model.extension() != ".md") seeds.push_back(model);
    }
    seeds.push_back(source / "assets" / "showcase.gltf");
    int loaded = 0;
    for (const fs::path& seed : seeds) {
        CAPTURE(seed.filename().string());
        const std::string error = load_like_fuzz_gltf(read_bytes(seed));
        CAPTURE(error);
        // Seeds named bad-* must be refused, the others must load.
        CHECK(error.empty() == (seed.filename().string().rfind("bad-", 0) != 0));
        loaded += error.empty();
    }
    CHECK(loaded >= 20);
}

TEST_CASE("fuzz inputs: every glTF crash reproducer is now a clean error") {
    for (const fs::path& input : files_in(kFuzz / "regressions" / "gltf")) {
        CAPTURE(input.filename().string());
        CHECK_FALSE(load_like_fuzz_gltf(read_bytes(input)).empty());
    }
}

} // TEST_SUITE
#endif

#if __has_include("vectors/run.hpp") && __has_include(<nlohmann/json.hpp>)
#include "vectors/run.hpp"

#include <nlohmann/json.hpp>

namespace {

// Runs the bytes as fuzz_vectors does and checks the tool's contract.
int run_like_fuzz_vectors(const std::string& bytes) {
    // In a child: status, '\0', stdout, '\0', stderr.
    const rob::Isolated run = rob::isolated([&bytes] {
        std::istringstream in(bytes);
        std::ostringstream out, err;
        const int status = vectors::run_frustum_vectors(in, out, err);
        return std::to_string(status) + '\0' + out.str() + '\0' + err.str();
    });
    REQUIRE_MESSAGE(run.finished, "run_frustum_vectors() did not return: ", run.how);
    const std::size_t a = run.value.find('\0'), b = run.value.find('\0', a + 1);
    REQUIRE(b != std::string::npos);
    const int status = std::stoi(run.value.substr(0, a));
    const std::string out = run.value.substr(a + 1, b - a - 1), err = run.value.substr(b + 1);
    CAPTURE(err);
    if (status == 0) {
        CHECK(err.empty());
        const auto response = nlohmann::json::parse(out, nullptr, false);
        CHECK_FALSE(response.is_discarded());
        CHECK(response.contains("cases"));
    } else {
        CHECK(status == 2);
        CHECK(out.empty());
        CHECK(err.rfind("frustum-vectors: ", 0) == 0);
        CHECK(err.find('\n') == err.size() - 1);
    }
    return status;
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("fuzz inputs: the frustum-vectors seed corpus keeps the tool's contract") {
    const auto seeds = files_in(kFuzz / "corpus" / "vectors");
    CHECK(seeds.size() >= 100);
    for (const fs::path& seed : seeds) {
        CAPTURE(seed.filename().string());
        const int status = run_like_fuzz_vectors(read_bytes(seed));
        // malformed-* seeds are the golden malformed requests: exit 2.
        CHECK((status == 2) == (seed.filename().string().rfind("malformed-", 0) == 0));
    }
}

TEST_CASE("fuzz inputs: every frustum-vectors crash reproducer now keeps the contract") {
    for (const fs::path& input : files_in(kFuzz / "regressions" / "vectors")) {
        CAPTURE(input.filename().string());
        run_like_fuzz_vectors(read_bytes(input));
    }
}

} // TEST_SUITE
#endif
