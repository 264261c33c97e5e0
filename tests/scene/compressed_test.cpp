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

#include <cstring>
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
    for (const compressed_models::Variant& variant : compressed_models::variants()) {
        const std::string file = variant.file;
        CAPTURE(file);
        std::string missing;
        const auto path = compressed_models::make(variant, dir.path(), missing);
        if (!path) {
            REQUIRE_MESSAGE(!missing.empty(), variant.tool << " failed to write " << variant.file);
            test_skips::skip(std::string(variant.file) + ": " + missing);
            continue;
        }
        const scene::Scene s = load(path->string());
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
    }
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

} // TEST_SUITE
