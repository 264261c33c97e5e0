// The Khronos glTF-Validator's test inputs (FRUSTUM_TEST_DATA/
// gltf-validator-corpus, not part of the repository: CTest corpus-validator,
// a skip when it is not set; also under the ASan + UBSan rerun). Every input
// loads or is refused with one line that names the file and the problem;
// nothing crashes or reads out of bounds (the sanitizers). The validator's
// own report beside each input says what is wrong with it: an input with no
// error loads (the exceptions below, with their reasons, also in
// docs/robustness.md), an input with an error that matters to drawing is
// refused. The counts are pinned, so a change of the loader's verdict on
// any input shows here.
#include "../sample_files.hpp"

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Report error codes that matter to drawing: what is drawn would read
// outside a buffer, index past an accessor, follow a broken reference, or
// the container or JSON itself is broken. An input with one of these must
// be refused. (Codes about animations, skins' joints, extensions' own
// properties, metadata or value ranges that are clamped or unused do not
// stop a draw and are left to the loader.)
const std::set<std::string>& drawing_errors() {
    static const std::set<std::string> codes = {
        // the file and its container (INVALID_JSON, IO_ERROR: see matters_to_drawing)
        "GLB_CHUNK_LENGTH_UNALIGNED", "GLB_CHUNK_TOO_BIG", "GLB_DUPLICATE_CHUNK", "GLB_EMPTY_CHUNK",
        "GLB_INVALID_MAGIC", "GLB_INVALID_VERSION", "GLB_LENGTH_MISMATCH", "GLB_LENGTH_TOO_SMALL",
        "GLB_UNEXPECTED_BIN_CHUNK", "GLB_UNEXPECTED_END_OF_CHUNK_DATA", "GLB_UNEXPECTED_END_OF_CHUNK_HEADER",
        "GLB_UNEXPECTED_END_OF_HEADER", "GLB_UNEXPECTED_FIRST_CHUNK", "BUFFER_MISSING_GLB_DATA",
        "UNKNOWN_ASSET_MAJOR_VERSION",
        // buffers, views and accessors out of bounds
        "BUFFER_BYTE_LENGTH_MISMATCH", "BUFFER_VIEW_TOO_LONG", "ACCESSOR_TOO_LONG", "ACCESSOR_INDEX_OOB",
        "ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE",
        // meshes that cannot be drawn as written
        "MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT", "MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT",
        "MESH_PRIMITIVE_INDICES_ACCESSOR_INVALID_FORMAT", "MESH_PRIMITIVE_MORPH_TARGET_INVALID_ATTRIBUTE_COUNT",
        // the node graph
        "NODE_LOOP",
    };
    return codes;
}

// A reference that does not resolve matters when it is in what is drawn
// (not inside an extension's object: lights, material variants).
bool drawing_reference(const std::string& pointer) {
    if (pointer.find("/extensions/") != std::string::npos) return false;
    for (const char* root : {"/scene", "/scenes/", "/nodes/", "/meshes/", "/accessors/", "/bufferViews/"}) {
        if (pointer.rfind(root, 0) == 0) return true;
    }
    return false;
}

// Whether one error of a report matters to drawing.
bool matters_to_drawing(const std::string& code, const std::string& pointer, const std::string& message) {
    if (code == "INVALID_JSON") return message.find("BOM found") == std::string::npos; // a UTF-8 BOM is read past
    if (code == "IO_ERROR") return pointer.rfind("/buffers/", 0) == 0; // an image no texture draws need not exist
    if (code == "UNRESOLVED_REFERENCE") return drawing_reference(pointer);
    return drawing_errors().count(code) != 0;
}

// Inputs without an error in their report that the loader refuses, and why
// (docs/robustness.md lists them too). Keyed by the path below the corpus.
const std::map<std::string, std::string>& refused_without_errors() {
    static const std::map<std::string, std::string> inputs = {
        {"base/data/accessor/unknown_type.gltf", "tinygltf refuses an accessor type it does not know, used or not"},
        {"base/data/accessor/valid.gltf", "a .gltf buffer without uri: tinygltf refuses it, used or not"},
        {"base/data/buffer/custom_property.gltf", "a .gltf buffer without uri: tinygltf refuses it, used or not"},
        {"base/data/json/integer_written_as_float.gltf", "a .gltf buffer without uri: tinygltf refuses it, used or not"},
        {"base/data/root/named_objects.gltf", "a .gltf buffer without uri: tinygltf refuses it, used or not"},
        {"base/data/root/unused_objects.gltf", "a .gltf buffer without uri: tinygltf refuses it, used or not"},
        {"base/data/mesh/valid.gltf", "an accessor without bufferView (all zeros): tinygltf refuses it"},
        {"base/data/buffer/valid_placeholder.glb", "a GLB buffer longer than its BIN chunk: tinygltf refuses it"},
        {"base/data/accessor_data/get_elements_matrix.gltf",
         "a MAT2 of bytes whose last column's padding is past its bufferView: the loader's bounds check "
         "counts every column padded to 4 bytes"},
        {"base/data/asset/min_version_valid.gltf", "asset.minVersion 2.1: the loader reads glTF 2.0 only"},
        {"base/data/buffer/data_uri.glb", "a data uri without ;base64: only base64 data uris are read"},
        {"base/data/buffer/non_relative_uri.gltf", "an http uri: only files inside the model's folder are read"},
        {"base/data/camera/perspective_yfov.gltf", "yfov 4 rad (at least pi) gives no perspective projection"},
        {"base/data/glb/extra_data.glb", "a byte after the GLB's declared length: a GLB is read as one whole"},
    };
    return inputs;
}

enum class Verdict { NoErrors, DrawingError, OtherError };

std::string name(Verdict v) {
    switch (v) {
    case Verdict::NoErrors: return "no errors";
    case Verdict::DrawingError: return "an error that matters to drawing";
    case Verdict::OtherError: return "other errors only";
    }
    return "?";
}

Verdict verdict_of(const Json& report) {
    const Json& issues = report.at("issues");
    if (issues.at("numErrors").get<int>() == 0) return Verdict::NoErrors;
    for (const Json& message : issues.at("messages")) {
        if (message.at("severity").get<int>() != 0) continue;
        if (matters_to_drawing(message.at("code"), message.value("pointer", ""), message.value("message", ""))) {
            return Verdict::DrawingError;
        }
    }
    return Verdict::OtherError;
}

std::vector<fs::path> inputs_under(const fs::path& root) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string name = entry.path().filename().string();
        const auto extension = entry.path().extension();
        if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

TEST_SUITE("corpus-validator") {

TEST_CASE("every glTF-Validator input loads or is refused in one line, as its report says it should") {
    const auto corpus = test_samples::corpus_folder("gltf-validator-corpus");
    if (!corpus) {
        return;
    }
    const std::vector<fs::path> inputs = inputs_under(*corpus);
    REQUIRE(inputs.size() == 372);
    // [verdict][loaded?] -> count
    std::map<Verdict, std::map<bool, int>> table;
    for (const fs::path& input : inputs) {
        const std::string relative = fs::relative(input, *corpus).generic_string();
        CAPTURE(relative);
        std::ifstream report_file(input.string() + ".report.json");
        REQUIRE_MESSAGE(report_file.good(), "no report beside " << relative);
        const Verdict verdict = verdict_of(Json::parse(report_file));

        const frustum::Result<scene::Scene> loaded = scene::load_gltf(input.string());
        const bool ok = loaded.ok();
        ++table[verdict][ok];
        if (!ok) {
            const std::string& error = loaded.error();
            CAPTURE(error);
            CHECK(error.rfind("scene::load_gltf(): " + input.string() + ": ", 0) == 0);
            CHECK(error.find('\n') == std::string::npos);
            CHECK(error.size() > ("scene::load_gltf(): " + input.string() + ": ").size() + 8);
        }
        if (verdict == Verdict::DrawingError) {
            CHECK_MESSAGE(!ok, relative << " has " << name(verdict) << " but loaded");
        }
        if (verdict == Verdict::NoErrors) {
            const auto exception = refused_without_errors().find(relative);
            const bool expected_ok = exception == refused_without_errors().end();
            CHECK_MESSAGE(ok == expected_ok, relative << (ok ? " loaded" : " was refused: " + loaded.error()));
        }
        MESSAGE((ok ? "loaded  " : "refused ") << relative << " (" << name(verdict) << ")"
                                              << (ok ? "" : ": " + loaded.error()));
    }
    for (const auto& [verdict, row] : table) {
        MESSAGE(name(verdict) << ": " << (row.count(true) ? row.at(true) : 0) << " loaded, "
                              << (row.count(false) ? row.at(false) : 0) << " refused");
    }
    // The pinned counts (docs/robustness.md): a change of any verdict shows.
    CHECK(table[Verdict::NoErrors][true] == 115);
    CHECK(table[Verdict::NoErrors][false] == int(refused_without_errors().size()));
    CHECK(table[Verdict::DrawingError][true] == 0);
    CHECK(table[Verdict::DrawingError][false] == 54);
    CHECK(table[Verdict::OtherError][true] == 131);
    CHECK(table[Verdict::OtherError][false] == 58);
}

} // TEST_SUITE
