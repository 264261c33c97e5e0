// KHR_mesh_quantization, EXT_meshopt_compression and
// KHR_draco_mesh_compression: each variant of the generated torus
// (compressed_models.hpp, written at test time) loads to the triangles of
// torus.gltf, in world space, within its stated tolerance. The pictures are
// compared in tests/gl/render_compressed_test.cpp.
#include "../skips.hpp"
#include "compressed_models.hpp"
#include "geometry_match.hpp"
#include "helpers.hpp"

#include <doctest/doctest.h>

#include <scene/load_gltf.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>

namespace {

// What each variant may differ by. Positions in metres (the torus spans
// 1.7 m); normals as |n - n'| of unit vectors; uv per component. Each is the
// quantization step its encoder uses (half a step of rounding, plus float
// rounding), as the comment says; the measured values are printed.
struct Tolerance {
    const char* file;
    float position_m, normal, uv;
};

const Tolerance kTolerances[] = {
    // SHORT normalized over 1.7 m: step 2.6e-5 m; BYTE normals: 1/127; USHORT uv: 1.5e-5.
    {"torus_quantized.gltf", 2e-5f, 0.012f, 1e-5f},
    // USHORT over 1.7 m: step 2.6e-5 m; SHORT normals; uv exact (i / 48, j / 32).
    {"torus_quantized_int.gltf", 2e-5f, 1e-4f, 1e-6f},
    // gltfpack's defaults: 14-bit positions (1.7 m / 16383), 8-bit normals, 12-bit uv.
    {"torus_gltfpack.gltf", 1e-4f, 0.012f, 2.5e-4f},
    {"torus_meshopt.gltf", 1e-4f, 0.012f, 2.5e-4f},
    {"torus_meshopt.glb", 1e-4f, 0.012f, 2.5e-4f},
    // Lossless: meshopt keeps the float bits.
    {"torus_meshopt_float.gltf", 1e-6f, 1e-6f, 1e-6f},
    // draco_transcoder's defaults: 11-bit positions (1.7 m / 2047), 8-bit normals, 10-bit uv.
    {"torus_draco.gltf", 6e-4f, 0.03f, 1e-3f},
};

const Tolerance& tolerance_of(const std::string& file) {
    for (const Tolerance& t : kTolerances) {
        if (file == t.file) return t;
    }
    FAIL("no tolerance for " << file);
    return kTolerances[0];
}

scene::Scene load(const std::string& path) {
    auto loaded = scene::load_gltf(path);
    REQUIRE_MESSAGE(loaded.ok(), loaded.error());
    return std::move(*loaded);
}

} // namespace

TEST_SUITE("scene") {

TEST_CASE("quantized and compressed tori load to the triangles of torus.gltf within their tolerance") {
    const scene::Scene original = load(compressed_models::torus_path());
    scene_test::TempDir dir;
    compressed_models::for_each_made_variant(dir.path(), [&](const compressed_models::Variant& variant,
                                                             const std::filesystem::path& path) {
        const std::string file = variant.file;
        const scene::Scene s = load(path.string());
        const Tolerance& t = tolerance_of(variant.file);
        const scene_test::GeometryDifference d = scene_test::compare_triangles(original, s, t.position_m);
        MESSAGE(file << " (" << std::string(variant.extension) << "): " << d.triangles_b << " triangles, max |dp| "
                             << d.max_position_m << " m, |dn| " << d.max_normal << ", |duv| " << d.max_uv
                             << ", unmatched " << d.unmatched);
        CHECK(d.triangles_b == d.triangles_a);
        CHECK_MESSAGE(d.unmatched == 0, d.first_unmatched);
        CHECK(d.max_position_m <= t.position_m);
        CHECK(d.max_normal <= t.normal);
        CHECK(d.max_uv <= t.uv);
    });
}

TEST_CASE("the comparison sees a moved vertex and a flipped winding") {
    const scene::Scene original = load(compressed_models::torus_path());
    scene::Scene moved = original;
    moved.meshes[0].primitives[0].positions[100].y += 0.5f; // 0.5 cm under the parent's scale 0.01
    const scene_test::GeometryDifference shifted = scene_test::compare_triangles(original, moved, 1e-3f);
    CHECK(shifted.unmatched == 6); // every triangle around vertex 100
    scene::Scene flipped = original;
    std::vector<std::uint32_t>& indices = flipped.meshes[0].primitives[0].indices;
    std::swap(indices[0], indices[1]);
    CHECK(scene_test::compare_triangles(original, flipped, 1e-3f).unmatched == 1);
    CHECK(scene_test::compare_triangles(original, original, 0.0f).unmatched == 0);
}

TEST_CASE("hostile compressed data is refused in one line naming what is wrong") {
    // Each case: a variant written by its tool, then changed.
    struct Hostile {
        const char* name;
        const char* variant;
        void (*change)(scene_test::Json& gltf, const std::filesystem::path& dir);
        const char* phrase;
    };
    using scene_test::Json;
    namespace fs = std::filesystem;
    static const Hostile cases[] = {
        {"meshopt: stream cut short", "torus_meshopt.gltf",
         [](Json& g, const fs::path&) { g["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 100; },
         "bufferView 1 EXT_meshopt_compression: the ATTRIBUTES data (100 bytes) does not decode to 1617 elements"},
        {"meshopt: count larger than the stream holds", "torus_meshopt.gltf",
         [](Json& g, const fs::path&) { g["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["count"] = 1000; },
         "does not decode to 1000 elements"},
        {"meshopt: count * byteStride past the bufferView", "torus_meshopt.gltf",
         [](Json& g, const fs::path&) { g["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["count"] = 3000000; },
         "decodes 3000000 x 4 bytes but the bufferView has 6468 bytes"},
        {"meshopt: source range past its buffer", "torus_meshopt.gltf",
         [](Json& g, const fs::path&) { g["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["byteOffset"] = 1u << 30; },
         "bufferView 1 EXT_meshopt_compression reads bytes [1073741824, "},
        {"meshopt: unknown mode", "torus_meshopt.gltf",
         [](Json& g, const fs::path&) { g["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["mode"] = "POINTS"; },
         "has mode \"POINTS\", expected ATTRIBUTES, TRIANGLES or INDICES"},
        {"meshopt: TRIANGLES count not a multiple of 3", "torus_meshopt.gltf",
         [](Json& g, const fs::path&) { g["bufferViews"][4]["extensions"]["EXT_meshopt_compression"]["count"] = 9215; },
         "has count 9215 for mode TRIANGLES, expected a multiple of 3"},
        {"meshopt: absurd fallback buffer", "torus_meshopt.gltf",
         [](Json& g, const fs::path&) { g["buffers"][1]["byteLength"] = 1ull << 40; },
         "EXT_meshopt_compression fallback buffer 1 has byteLength 1099511627776; the fallback buffers' bytes is over "
         "the budget of 256 MiB (raise it with --max-memory-mb)"},
        {"draco: stream cut short", "torus_draco.gltf",
         [](Json& g, const fs::path&) { g["bufferViews"][0]["byteLength"] = 200; },
         "mesh 0 primitive 0 KHR_draco_mesh_compression: the Draco data (bufferView 0, 200 bytes) does not decode"},
        {"draco: indices count disagrees", "torus_draco.gltf",
         [](Json& g, const fs::path&) { g["accessors"][0]["count"] = 9213; },
         "decodes to 9216 indices but its indices accessor 0 has count 9213"},
        {"draco: point count disagrees", "torus_draco.gltf",
         [](Json& g, const fs::path&) { g["accessors"][1]["count"] = 1616; },
         "decodes to 1617 points but POSITION (accessor 1) has count 1616"},
        {"draco: absurd accessor count", "torus_draco.gltf",
         [](Json& g, const fs::path&) { g["accessors"][1]["count"] = 4000000000u; },
         "bytes by its accessors' counts, over the memory budget left (268435456 bytes; raise it with --max-memory-mb)"},
        {"draco: attribute id the data lacks", "torus_draco.gltf",
         [](Json& g, const fs::path&) {
             g["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["POSITION"] = 7;
         },
         "maps POSITION to Draco attribute 7, which the decoded data does not have"},
        {"draco: bufferView out of range", "torus_draco.gltf",
         [](Json& g, const fs::path&) {
             g["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = 9;
         },
         "tinygltf: accessor[0] invalid bufferView"}, // the indices get the extension's bufferView (parse_model.cpp)
        {"quantized: a format the extension does not allow", "torus_quantized.gltf",
         [](Json& g, const fs::path&) { g["accessors"][g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"].get<int>()]["componentType"] = 5121; },
         "allowed: VEC3 of FLOAT or normalized BYTE/SHORT"},
        {"quantized: integer POSITION without the extension", "torus_quantized.gltf",
         [](Json& g, const fs::path&) { g.erase("extensionsUsed"); g.erase("extensionsRequired"); },
         "NORMAL of mesh 0 primitive 0 (accessor 1) is VEC3 with componentType 5120 (BYTE) normalized; allowed: VEC3 FLOAT"},
    };
    scene_test::TempDir dir;
    for (const Hostile& c : cases) {
        const std::string name = c.name;
        CAPTURE(name);
        const auto variant = std::find_if(compressed_models::variants().begin(), compressed_models::variants().end(),
                                          [&](const compressed_models::Variant& v) { return std::string(v.file) == c.variant; });
        REQUIRE(variant != compressed_models::variants().end());
        const auto path = compressed_models::make_or_skip(*variant, dir.path(), name);
        if (!path) {
            continue;
        }
        Json gltf = scene_test::read_json(*path);
        c.change(gltf, dir.path());
        const fs::path changed = dir.path() / ("changed-" + std::string(c.variant));
        scene_test::write_text(changed, gltf.dump());
        const auto loaded = scene::load_gltf(changed.string());
        REQUIRE_FALSE(loaded.ok());
        const std::string& error = loaded.error();
        CAPTURE(error);
        CHECK(error.find('\n') == std::string::npos);
        CHECK(error.find(c.phrase) != std::string::npos);
    }
}

TEST_CASE("the compressed fuzz seeds (scripts/gltf_seeds.py) are refused by their decoder") {
    const std::string seeds = std::string(FRUSTUM_SOURCE_DIR) + "/tests/fuzz/corpus/gltf/";
    const auto meshopt = scene::load_gltf(seeds + "bad-meshopt-garbage.gltf");
    REQUIRE_FALSE(meshopt.ok());
    CHECK(meshopt.error().find("bufferView 1 EXT_meshopt_compression: the ATTRIBUTES data (72 bytes) does not decode "
                               "to 48 elements of 12 bytes") != std::string::npos);
    const auto draco = scene::load_gltf(seeds + "bad-draco-garbage.gltf");
    REQUIRE_FALSE(draco.ok());
    CHECK(draco.error().find("mesh 0 primitive 0 KHR_draco_mesh_compression: the Draco data (bufferView 0, 72 bytes) "
                             "does not decode") != std::string::npos);
}

} // TEST_SUITE
