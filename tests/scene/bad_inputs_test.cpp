// Table of broken files, each made by mutating a good sample in a temp
// folder: every one must fail cleanly with a message naming the file and the
// broken rule (checked by exact key phrases).
#include "helpers.hpp"

#include "scene/load_gltf.hpp"
#include "support/case_table.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

using scene_test::Bytes;
using scene_test::Json;

namespace {

namespace fs = std::filesystem;

struct Fixture {
    scene_test::TempDir dir;
    std::string model = (dir.path() / "model.gltf").string();
    scene::LoadOptions options;
};

struct BadInput {
    const char* input; // the case's name
    std::function<void(Fixture&)> make;
    std::vector<std::string> phrases;
};

// The sample's JSON, changed, written as the fixture's model.gltf.
std::function<void(Fixture&)> edit(const char* sample, std::function<void(Json&)> change) {
    return [sample, change](Fixture& f) {
        Json gltf = scene_test::read_json(scene_test::model_path(sample));
        change(gltf);
        scene_test::write_text(f.model, gltf.dump());
    };
}

// The sample's buffer 0 bytes, changed in place.
std::function<void(Json&)> poke_buffer(std::function<void(Bytes&)> change) {
    return [change](Json& gltf) {
        Bytes bytes = scene_test::buffer0(gltf);
        change(bytes);
        scene_test::set_buffer0(gltf, bytes);
    };
}

void put_u16(Bytes& bytes, std::size_t offset, std::uint16_t value) {
    bytes[offset] = std::uint8_t(value);
    bytes[offset + 1] = std::uint8_t(value >> 8);
}

// Sparse index k (UNSIGNED_SHORT) of accessor 0 set to `value`, found
// through the JSON (the generated sparse.gltf).
std::function<void(Json&)> poke_sparse_index(std::size_t k, std::uint16_t value) {
    return [k, value](Json& gltf) {
        const Json& indices = gltf["accessors"][0]["sparse"]["indices"];
        REQUIRE(indices["componentType"] == 5123);
        const std::size_t offset = gltf["bufferViews"][indices["bufferView"].get<std::size_t>()]["byteOffset"];
        poke_buffer([&](Bytes& b) { put_u16(b, offset + 2 * k, value); })(gltf);
    };
}

void put_u32(Bytes& bytes, std::size_t offset, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes[offset + i] = std::uint8_t(value >> (8 * i));
}

std::uint32_t get_u32(const Bytes& bytes, std::size_t offset) {
    return std::uint32_t(bytes[offset]) | std::uint32_t(bytes[offset + 1]) << 8 |
           std::uint32_t(bytes[offset + 2]) << 16 | std::uint32_t(bytes[offset + 3]) << 24;
}

// Box as a .glb (model.glb), then the bytes changed.
std::function<void(Fixture&)> glb(std::function<void(Bytes&)> change) {
    return [change](Fixture& f) {
        const Json gltf = scene_test::read_json(scene_test::model_path("box.gltf"));
        Bytes bytes = scene_test::make_glb(gltf, scene_test::buffer0(gltf));
        change(bytes);
        f.model = (f.dir.path() / "model.glb").string();
        scene_test::write_bytes(f.model, bytes);
    };
}

// Box with its buffer in "box.bin" next to it, then buffer 0's uri replaced.
std::function<void(Fixture&)> buffer_uri(std::string uri) {
    return [uri](Fixture& f) {
        Json gltf = scene_test::read_json(scene_test::model_path("box.gltf"));
        const Bytes bytes = scene_test::buffer0(gltf);
        scene_test::write_bytes(f.dir.path() / "box.bin", bytes);
        scene_test::write_bytes(f.dir.outside() / "x.bin", bytes); // must never be read
        gltf["buffers"][0]["uri"] = uri;
        scene_test::write_text(f.model, gltf.dump());
    };
}

std::string nested_arrays(std::size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

const std::vector<BadInput>& bad_inputs() {
    static const std::vector<BadInput> cases = {
        // --- the file itself
        {"missing file", [](Fixture&) {}, {"model.gltf\" does not exist"}},
        {"empty file", [](Fixture& f) { scene_test::write_text(f.model, ""); }, {"the file is empty"}},
        {"PNG bytes", [](Fixture& f) { scene_test::write_bytes(f.model, {0x89, 'P', 'N', 'G', 13, 10, 26, 10}); },
         {"not a glTF file", "89 50 4E 47"}},
        {"JSON array root", [](Fixture& f) { scene_test::write_text(f.model, "[1, 2, 3]"); }, {"not a glTF file"}},
        {"truncated JSON", [](Fixture& f) {
             std::string text = scene_test::read_json(scene_test::model_path("box.gltf")).dump();
             scene_test::write_text(f.model, text.substr(0, text.size() / 2));
         }, {"invalid JSON", "parse error"}},
        {"required extension", edit("box.gltf", [](Json& g) {
             g["extensionsUsed"] = {"KHR_materials_variants"};
             g["extensionsRequired"] = {"KHR_materials_variants"};
         }), {"the file requires glTF extension KHR_materials_variants, which is not supported (supported: "
          "EXT_mesh_gpu_instancing, EXT_meshopt_compression, KHR_draco_mesh_compression, KHR_materials_unlit, "
          "KHR_mesh_quantization, KHR_texture_transform)"}},
        {"no asset", edit("box.gltf", [](Json& g) { g.erase("asset"); }), {"tinygltf", "\"asset\" object not found"}},
        {"deep nesting", [](Fixture& f) {
             std::string text = scene_test::read_json(scene_test::model_path("box.gltf")).dump();
             text.insert(1, "\"extras\":" + nested_arrays(100000) + ",");
             scene_test::write_text(f.model, text);
         }, {"JSON nesting depth exceeds 64"}},
        {"file over the size limit", [](Fixture& f) {
             f.options.max_file_bytes = 100;
             scene_test::write_text(f.model, scene_test::read_json(scene_test::model_path("box.gltf")).dump());
         }, {"bytes, more than the limit of 100"}},

        // --- GLB container
        {"GLB truncated", glb([](Bytes& b) { b.resize(b.size() - 8); }), {"GLB header length", "does not match the file size"}},
        {"GLB header only", [](Fixture& f) {
             f.model = (f.dir.path() / "model.glb").string();
             scene_test::write_bytes(f.model, {'g', 'l', 'T', 'F', 2, 0, 0, 0});
         }, {"truncated GLB", "needs 12"}},
        {"GLB version 1", glb([](Bytes& b) { put_u32(b, 4, 1); }), {"GLB version 1 is not supported"}},
        {"GLB JSON chunk longer than the file", glb([](Bytes& b) { put_u32(b, 12, 1u << 30); }),
         {"GLB chunk 0 length 1073741824", "larger than the"}},
        {"GLB BIN chunk 8 bytes too long", glb([](Bytes& b) {
             const std::size_t bin = 20 + get_u32(b, 12);
             put_u32(b, bin, get_u32(b, bin) + 8);
         }), {"GLB chunk 1 length", "larger than the"}},
        {"GLB first chunk not JSON", glb([](Bytes& b) { put_u32(b, 16, 0x004E4942); }), {"GLB chunk 0 has type", "expected JSON"}},
        {"GLB BIN shorter than the buffer", [](Fixture& f) {
             const Json gltf = scene_test::read_json(scene_test::model_path("box.gltf"));
             const Bytes bin = scene_test::buffer0(gltf);
             Bytes bytes = scene_test::make_glb(gltf, Bytes(bin.begin(), bin.begin() + 100));
             // The JSON now says byteLength 100; make it claim all 648 bytes.
             const std::string from = "\"byteLength\":100}", to = "\"byteLength\":648}";
             auto at = std::search(bytes.begin(), bytes.end(), from.begin(), from.end());
             REQUIRE(at != bytes.end());
             std::copy(to.begin(), to.end(), at);
             f.model = (f.dir.path() / "model.glb").string();
             scene_test::write_bytes(f.model, bytes);
         }, {"tinygltf", "Invalid `byteLength'", "binary size = 100"}},

        // --- uris and the sandbox
        {"buffer uri \".\"", buffer_uri("."), {"buffer 0 uri \".\" names a folder"}},
        {"buffer uri \"\"", buffer_uri(""), {"buffer 0 uri \"\" is empty"}},
        {"buffer uri \"../x.bin\"", buffer_uri("../outside/x.bin"), {"buffer 0 uri \"../outside/x.bin\"", "outside the model folder"}},
        {"buffer uri via sub/../..", buffer_uri("sub/../../outside/x.bin"), {"outside the model folder"}},
        {"buffer uri percent-encoded ..", buffer_uri("%2e%2e/outside/x.bin"), {"outside the model folder"}},
        {"buffer uri absolute", [](Fixture& f) {
             buffer_uri((f.dir.outside() / "x.bin").string())(f);
         }, {"is an absolute path"}},
        {"buffer uri with a scheme", buffer_uri("file:///etc/hostname"), {"has a scheme"}},
        {"buffer uri with a backslash", buffer_uri("..\\outside\\x.bin"), {"backslash"}},
        {"buffer uri to a folder", [](Fixture& f) {
             fs::create_directories(f.dir.path() / "folder");
             buffer_uri("folder/")(f);
         }, {"names a folder"}},
        {"buffer file missing", buffer_uri("missing.bin"), {"File not found", "missing.bin\" does not exist"}},
        {"buffer symlink leading out", [](Fixture& f) {
             buffer_uri("link.bin")(f);
             fs::create_symlink(f.dir.outside() / "x.bin", f.dir.path() / "link.bin");
         }, {"link.bin\" resolves to", "outside the model folder"}},
        {"buffer file over the size limit", [](Fixture& f) {
             buffer_uri("box.bin")(f);
             f.options.max_file_bytes = 1000; // the .gltf is smaller, box.bin too: 648
             scene_test::write_bytes(f.dir.path() / "box.bin", Bytes(2000, 0));
         }, {"box.bin\" has 2000 bytes, more than the limit of 1000"}},
        {"image uri outside", edit("box_textured.gltf", [](Json& g) { g["images"][0]["uri"] = "../tex.png"; }),
         {"image 0 uri \"../tex.png\"", "outside the model folder"}},
        {"image file missing", edit("box_textured.gltf", [](Json& g) { g["images"][0]["uri"] = "tex.png"; }),
         {"image 0 (uri \"tex.png\") could not be read", "does not exist"}},

        // --- buffers, bufferViews, accessors
        {"buffer byteLength larger than its data", edit("box.gltf", [](Json& g) { g["buffers"][0]["byteLength"] = 1000; }),
         {"tinygltf", "Failed to decode 'uri'"}},
        {"bufferView beyond the buffer", edit("box.gltf", [](Json& g) { g["bufferViews"][0]["byteLength"] = 100; }),
         {"bufferView 0 covers bytes [576, 676) of buffer 0 which has 648 bytes"}},
        {"bufferView buffer index", edit("box.gltf", [](Json& g) { g["bufferViews"][0]["buffer"] = 3; }),
         {"bufferView 0 uses buffer 3 but the file has 1 buffers"}},
        {"stride smaller than the element", edit("box.gltf", [](Json& g) { g["bufferViews"][1]["byteStride"] = 8; }),
         {"accessor 1 (NORMAL of mesh 0 primitive 0) has 12-byte elements", "byteStride 8"}},
        {"accessor over-read", edit("box.gltf", [](Json& g) { g["accessors"][2]["count"] = 48; }),
         {"accessor 2 (POSITION of mesh 0 primitive 0) reads bytes [288, 864) of bufferView 1 which has 576 bytes"}},
        {"accessor count beyond the view", edit("box.gltf", [](Json& g) { g["accessors"][2]["count"] = 100000; }),
         {"accessor 2 (POSITION of mesh 0 primitive 0) has count 100000"}},
        {"accessor bufferView index", edit("box.gltf", [](Json& g) { g["accessors"][1]["bufferView"] = 9; }),
         {"accessor 1 (NORMAL of mesh 0 primitive 0) uses bufferView 9 but the file has 2 bufferViews"}},
        {"accessor misaligned", edit("box.gltf", [](Json& g) { g["accessors"][2]["byteOffset"] = 286; }),
         {"accessor 2 (POSITION of mesh 0 primitive 0) starts at byte 286", "not a multiple of its 4-byte component size"}},
        {"accessor normalized float", edit("box.gltf", [](Json& g) { g["accessors"][2]["normalized"] = true; }),
         {"is normalized but has componentType 5126 (FLOAT)"}},
        {"accessor componentType INT", edit("box.gltf", [](Json& g) { g["accessors"][0]["componentType"] = 5124; }),
         {"accessor 0 (indices of mesh 0 primitive 0) has componentType 5124"}},
        {"accessor count 0", edit("box.gltf", [](Json& g) { g["accessors"][1]["count"] = 0; }), {"has count 0, expected >= 1"}},
        {"sparse index out of range", edit("sparse.gltf", poke_sparse_index(0, 99)),
         {"accessor 0 (POSITION of mesh 0 primitive 0) sparse index 0 is 99", "below count 8"}},
        {"sparse indices not increasing", edit("sparse.gltf", poke_sparse_index(1, 1)),
         {"sparse index 1 is 1", "increase strictly"}},
        {"sparse count above count", edit("sparse.gltf", [](Json& g) { g["accessors"][0]["sparse"]["count"] = 9; }),
         {"has sparse.count 9, expected 1..8"}},

        // --- meshes
        {"index value out of range", edit("box.gltf", poke_buffer([](Bytes& b) { put_u16(b, 576, 999); })),
         {"indices of mesh 0 primitive 0 (accessor 0) has value 999 at position 0 but the primitive has 24 vertices"}},
        {"indices accessor out of range", edit("box.gltf", [](Json& g) { g["meshes"][0]["primitives"][0]["indices"] = 9; }),
         {"tinygltf", "indices accessor out of bounds"}},
        {"indices of type VEC3", edit("triangle.gltf", [](Json& g) { g["meshes"][0]["primitives"][0]["indices"] = 1; }),
         {"indices of mesh 0 primitive 0 (accessor 1) is VEC3", "allowed: SCALAR"}},
        {"POSITION of UNSIGNED_BYTE", edit("box.gltf", [](Json& g) { g["accessors"][2]["componentType"] = 5121; }),
         {"POSITION of mesh 0 primitive 0 (accessor 2) is VEC3 with componentType 5121 (UNSIGNED_BYTE); allowed: VEC3 FLOAT"}},
        {"NORMAL as VEC2", edit("box.gltf", [](Json& g) { g["accessors"][1]["type"] = "VEC2"; }),
         {"NORMAL of mesh 0 primitive 0 (accessor 1) is VEC2"}},
        {"attribute accessor out of range", edit("box.gltf", [](Json& g) { g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 9; }),
         {"NORMAL of mesh 0 primitive 0 uses accessor 9 but the file has 3 accessors"}},
        {"attribute counts differ", edit("box.gltf", [](Json& g) { g["accessors"][1]["count"] = 23; }),
         {"NORMAL of mesh 0 primitive 0 (accessor 1) has 23 elements but POSITION has 24"}},
        {"primitive mode 9", edit("box.gltf", [](Json& g) { g["meshes"][0]["primitives"][0]["mode"] = 9; }),
         {"mesh 0 primitive 0 has mode 9, expected 0..6"}},
        {"primitive material out of range", edit("box.gltf", [](Json& g) { g["meshes"][0]["primitives"][0]["material"] = 5; }),
         {"uses material 5 but the file has 1 materials"}},
        {"mesh without primitives", edit("box.gltf", [](Json& g) { g["meshes"][0]["primitives"] = Json::array(); }),
         {"mesh 0 has no primitives"}},

        // --- images, textures, materials
        {"image bufferView beyond the buffer", edit("box_textured.gltf", [](Json& g) {
             scene_test::image0_into_buffer_view(g);
             g["bufferViews"].back()["byteLength"] = 1u << 20;
         }), {"image 0 uses bufferView 4 which covers bytes [840, ", "of buffer 0 which has"}},
        {"image bufferView index", edit("box_textured.gltf", [](Json& g) {
             scene_test::image0_into_buffer_view(g);
             g["images"][0]["bufferView"] = 9;
         }), {"tinygltf", "image[0] bufferView \"9\" not found"}},
        {"image bytes not an image", edit("box_textured.gltf", [](Json& g) {
             g["images"][0]["uri"] = "data:image/png;base64," + scene_test::base64_encode(Bytes(64, 7));
         }), {"image 0: the image is neither PNG nor JPEG (first bytes 07 07 07)"}},
        {"image over the pixel limit", [](Fixture& f) {
             f.options.max_image_pixels = 15;
             scene_test::write_text(f.model, scene_test::read_json(scene_test::model_path("box_textured.gltf")).dump());
         }, {"image 0: image is 4 x 4 pixels, the limit is 15 pixels"}},
        {"texture source out of range", edit("box_textured.gltf", [](Json& g) { g["textures"][0]["source"] = 3; }),
         {"texture 0 uses image 3 but the file has 1 images"}},
        {"material texture index out of range", edit("box_textured.gltf", [](Json& g) {
             g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 4;
         }), {"material 0 baseColorTexture uses texture 4 but the file has 1 textures"}},
        {"normalTexture index out of range", edit("box_textured.gltf", [](Json& g) {
             g["materials"][0]["normalTexture"] = {{"index", 2}};
         }), {"material 0 normalTexture uses texture 2"}},

        // --- nodes and scenes
        {"node cycle", edit("box.gltf", [](Json& g) { g["nodes"][1]["children"] = {0}; }),
         {"the node graph has a cycle of 2 nodes (parent -> child): 1 -> 0 -> 1"}},
        {"node is its own child", edit("box.gltf", [](Json& g) { g["nodes"][0]["children"] = {0, 1}; }),
         {"the node graph has a cycle of 1 node (parent -> child): 0 -> 0"}},
        {"child index out of range", edit("box.gltf", [](Json& g) { g["nodes"][0]["children"] = {7}; }),
         {"node 0 has child 7 but the file has 2 nodes"}},
        {"node with two parents", edit("box.gltf", [](Json& g) {
             g["nodes"].push_back({{"children", {1}}});
             g["scenes"][0]["nodes"].push_back(2);
         }), {"node 1 is a child of both node 0 and node 2"}},
        {"node mesh out of range", edit("box.gltf", [](Json& g) { g["nodes"][1]["mesh"] = 5; }),
         {"node 1 uses mesh 5 but the file has 1 meshes"}},
        {"node camera out of range", edit("box.gltf", [](Json& g) { g["nodes"][1]["camera"] = 0; }),
         {"node 1 uses camera 0 but the file has 0 cameras"}},
        {"node matrix of 15", edit("box.gltf", [](Json& g) { g["nodes"][0]["matrix"].erase(15); }),
         {"node 0 matrix has 15 elements, expected 16"}},
        {"node translation of 2", edit("box.gltf", [](Json& g) { g["nodes"][1]["translation"] = {1, 2}; }),
         {"node 1 translation has 2 elements, expected 3"}},
        {"node rotation zero", edit("box.gltf", [](Json& g) { g["nodes"][1]["rotation"] = {0, 0, 0, 0}; }),
         {"node 1 rotation quaternion has length 0, expected 1"}},
        {"scene root is a child", edit("box.gltf", [](Json& g) { g["scenes"][0]["nodes"] = {0, 1}; }),
         {"scene 0 lists node 1 as a root, but it is a child of node 0"}},
        {"scene node out of range", edit("box.gltf", [](Json& g) { g["scenes"][0]["nodes"] = {5}; }),
         {"scene 0 lists node 5 but the file has 2 nodes"}},
        {"default scene out of range", edit("box.gltf", [](Json& g) { g["scene"] = 3; }),
         {"the default scene is 3 but the file has 1 scenes"}},
        {"requested scene out of range", [](Fixture& f) {
             f.options.scene_index = 4;
             scene_test::write_text(f.model, scene_test::read_json(scene_test::model_path("box.gltf")).dump());
         }, {"scene 4 was requested but the file has 1 scenes"}},
        {"mirror node of zero size", edit("box.gltf", [](Json& g) {
             g["nodes"][1]["name"] = "mirror";
             g["nodes"][1]["scale"] = {0, 1, 1};
         }), {"node \"mirror\" has a degenerate world transform"}},

        // --- cameras
        {"camera znear 0", edit("cameras.gltf", [](Json& g) { g["cameras"][0]["perspective"]["znear"] = 0; }),
         {"camera 0 znear 0 must be > 0"}},
        {"camera znear negative", edit("cameras.gltf", [](Json& g) { g["cameras"][0]["perspective"]["znear"] = -0.5; }),
         {"camera 0 znear -0.5 must be > 0"}},
        {"camera zfar below znear", edit("cameras.gltf", [](Json& g) { g["cameras"][0]["perspective"]["zfar"] = 0.005; }),
         {"camera 0 zfar 0.005 must be > znear 0.01"}},
        {"camera yfov pi", edit("cameras.gltf", [](Json& g) { g["cameras"][0]["perspective"]["yfov"] = 3.5; }),
         {"camera 0 yfov 3.5 rad is not in (0, pi)"}},
        {"camera aspect negative", edit("cameras.gltf", [](Json& g) { g["cameras"][0]["perspective"]["aspectRatio"] = -1; }),
         {"camera 0 aspectRatio -1 must be > 0"}},
        {"orthographic xmag 0", edit("cameras.gltf", [](Json& g) { g["cameras"][1]["orthographic"]["xmag"] = 0; }),
         {"camera 1 xmag 0 and ymag 1 must be finite and non-zero"}},
        {"orthographic zfar equal znear", edit("cameras.gltf", [](Json& g) { g["cameras"][1]["orthographic"]["zfar"] = 0.01; }),
         {"camera 1 zfar 0.01 must be > znear 0.01"}},
        {"camera node of zero scale", edit("cameras.gltf", [](Json& g) { g["nodes"][1]["scale"] = {0, 0, 0}; }),
         {"camera node 1 has a degenerate world transform"}},
    };
    return cases;
}

} // namespace

TEST_SUITE("scene") {

TEST_CASE("bad inputs fail with a message naming the file and the broken rule") {
    support::for_each_case(bad_inputs(), 20, [](const BadInput& bad) {
        Fixture fixture;
        bad.make(fixture);
        const frustum::Result<scene::Scene> result = scene::load_gltf(fixture.model, fixture.options);
        REQUIRE_FALSE(result.ok());
        support::check_message(result.error(), "scene::load_gltf(): " + fixture.model + ": ", bad.phrases, false);
    });
}

} // TEST_SUITE
