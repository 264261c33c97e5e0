// Quantized and compressed variants of the generated torus
// (tests/data/gltf-models/torus.gltf), written at test time into a folder:
// the KHR_mesh_quantization ones by scripts/make_feature_gltf.py
// --quantized, the others by Debian's tools (gltfpack for
// EXT_meshopt_compression, draco_transcoder for KHR_draco_mesh_compression).
// Nothing third-party is committed. Header-only: the scene and gl suites
// both use it. Test-only code.
#pragma once

#include "../skips.hpp"

#include <support/child_process.hpp>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace compressed_models {

struct Variant {
    const char* file;      // written into the folder
    const char* tool;      // what must be installed to write it
    const char* extension; // what it exercises
};

inline const std::vector<Variant>& variants() {
    static const std::vector<Variant> list = {
        {"torus_quantized.gltf", "python3", "KHR_mesh_quantization (normalized SHORT/BYTE/UNSIGNED_SHORT)"},
        {"torus_quantized_int.gltf", "python3", "KHR_mesh_quantization (plain UNSIGNED_SHORT/UNSIGNED_BYTE)"},
        {"torus_gltfpack.gltf", "gltfpack", "KHR_mesh_quantization as gltfpack writes it"},
        {"torus_meshopt.gltf", "gltfpack", "EXT_meshopt_compression + KHR_mesh_quantization"},
        {"torus_meshopt.glb", "gltfpack", "EXT_meshopt_compression in a .glb"},
        {"torus_meshopt_float.gltf", "gltfpack", "EXT_meshopt_compression of float attributes"},
        {"torus_draco.gltf", "draco_transcoder", "KHR_draco_mesh_compression"},
    };
    return list;
}

inline std::string torus_path() { return std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-models/torus.gltf"; }

inline bool installed(const std::string& tool) { return !support::find_on_path(tool).empty(); }

// `tool` (found on PATH) with `args`, through tests/support's runner: no
// shell, at most its 120 s (then a failure naming the command); true when it
// exited 0. Its output is dropped.
inline bool run(const std::string& tool, const std::vector<std::string>& args) {
    support::Launch launch;
    launch.args = args;
    const support::Outcome outcome = support::run(support::find_on_path(tool), launch);
    return outcome.exit_status == 0;
}

inline nlohmann::json read_json(const std::filesystem::path& path) {
    std::ifstream file(path);
    return nlohmann::json::parse(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

inline void write_json(const std::filesystem::path& path, const nlohmann::json& json) {
    std::ofstream(path) << json.dump();
}

// draco_transcoder 1.5.5 refuses the torus's data-uri texture ("Invalid
// source data for the texture"): it transcodes the torus without it, and the
// material, texture, image and sampler are put back after.
inline bool make_draco(const std::filesystem::path& dir, const std::string& file) {
    const nlohmann::json torus = read_json(torus_path());
    nlohmann::json bare = torus;
    for (const char* key : {"images", "textures", "samplers"}) bare.erase(key);
    bare["materials"][0]["pbrMetallicRoughness"].erase("baseColorTexture");
    write_json(dir / "torus_untextured.gltf", bare);
    if (!run("draco_transcoder", {"-i", (dir / "torus_untextured.gltf").string(), "-o", (dir / file).string()})) {
        return false;
    }
    nlohmann::json draco = read_json(dir / file);
    for (const char* key : {"materials", "images", "textures", "samplers"}) {
        if (torus.contains(key)) draco[key] = torus[key];
    }
    write_json(dir / file, draco);
    return true;
}

// Writes `variant` into `dir` (with its .bin when the tool writes one).
// Absent: its tool is not installed (`missing` says which) or failed
// (`missing` empty: a failure of the test, not a skip).
inline std::optional<std::filesystem::path> make(const Variant& variant, const std::filesystem::path& dir,
                                                 std::string& missing) {
    missing.clear();
    if (!installed(variant.tool)) {
        missing = std::string(variant.tool) + " is not installed (scripts/install-deps.sh)";
        return std::nullopt;
    }
    const std::string file = variant.file;
    const std::filesystem::path out = dir / file;
    const std::vector<std::string> gltfpack = {"-i", torus_path(), "-o", out.string()};
    const auto with = [&gltfpack](std::vector<std::string> more) {
        more.insert(more.begin(), gltfpack.begin(), gltfpack.end());
        return more;
    };
    bool made = false;
    if (file == "torus_quantized.gltf" || file == "torus_quantized_int.gltf") {
        made = std::filesystem::exists(out) ||
               run("python3", {std::string(FRUSTUM_SOURCE_DIR) + "/scripts/make_feature_gltf.py", "--quantized",
                               dir.string()});
    } else if (file == "torus_gltfpack.gltf") {
        made = run("gltfpack", gltfpack);
    } else if (file == "torus_meshopt.gltf" || file == "torus_meshopt.glb") {
        made = run("gltfpack", with({"-c"}));
    } else if (file == "torus_meshopt_float.gltf") {
        made = run("gltfpack", with({"-c", "-noq"}));
    } else if (file == "torus_draco.gltf") {
        made = make_draco(dir, file);
    }
    if (!made || !std::filesystem::exists(out)) {
        return std::nullopt;
    }
    return out;
}

// make() as the tests use it: a missing tool is a skip (tests/skips.hpp)
// named after `what`, a tool that fails is a failure of the test.
inline std::optional<std::filesystem::path> make_or_skip(const Variant& variant, const std::filesystem::path& dir,
                                                         const std::string& what) {
    std::string missing;
    auto path = make(variant, dir, missing);
    if (!path) {
        REQUIRE_MESSAGE(!missing.empty(), variant.tool << " failed to write " << variant.file);
        test_skips::skip(what + ": " + missing);
    }
    return path;
}

// Makes every variant in `dir` (make_or_skip: a missing tool skips it) and
// runs check(variant, path) on each one made, its file name captured.
template <class Check>
void for_each_made_variant(const std::filesystem::path& dir, Check check) {
    for (const Variant& variant : variants()) {
        const std::string file = variant.file;
        CAPTURE(file);
        const auto path = make_or_skip(variant, dir, file);
        if (path) check(variant, *path);
    }
}

} // namespace compressed_models
