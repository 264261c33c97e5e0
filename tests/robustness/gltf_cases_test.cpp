// Bad glTF files: each row writes a broken file (mostly Triangle.gltf with
// one thing changed) into a private folder and names the phrases the
// loader's error must contain. The loader must refuse cleanly: no crash, no
// hang (a FIFO must never be opened), no read outside the model's folder.
// Each load runs in a child process: a crash or hang fails its row only.
#if __has_include("scene/load_gltf.hpp") && __has_include(<nlohmann/json.hpp>)
#include "support.hpp"

#include "gltf_layout.hpp"

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct Model {
    support::TempDir dir;
    std::string path = (dir / "model.gltf").string();
    scene::LoadOptions options;
};

struct GltfCase {
    const char* input;
    std::function<void(Model&)> make;
    std::vector<std::string> phrases;
};

Json triangle() {
    std::ifstream file(std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-models/triangle.gltf");
    REQUIRE(file.good());
    return Json::parse(file);
}

std::function<void(Model&)> edit(std::function<void(Json&)> change) {
    return [change](Model& m) {
        Json gltf = triangle();
        change(gltf);
        support::write_file(m.path, gltf.dump());
    };
}

std::function<void(Model&)> text(std::string bytes) {
    return [bytes](Model& m) { support::write_file(m.path, bytes); };
}

// "\x89PNG" + IHDR of the given size (CRC not checked by stb) + no data.
std::string png_header(unsigned width, unsigned height) {
    std::string png = "\x89PNG\r\n\x1a\n";
    png += std::string("\0\0\0\x0dIHDR", 8);
    for (unsigned v : {width, height}) {
        for (int shift = 24; shift >= 0; shift -= 8) png += char((v >> shift) & 0xff);
    }
    png += std::string("\x08\x06\0\0\0", 5) + std::string(4, '\0');
    return png;
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto byte = [&bytes](std::size_t i) { return i < bytes.size() ? unsigned(std::uint8_t(bytes[i])) : 0u; };
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const unsigned v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
        const std::size_t digits_used = std::min<std::size_t>(bytes.size() - i, 3) + 1; // 2, 3 or 4
        for (std::size_t k = 0; k < 4; ++k) out += k < digits_used ? digits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// Triangle with a textured material whose image is `image`.
std::function<void(Model&)> with_image(Json image) {
    return edit([image](Json& g) {
        g["images"] = Json::array({image}); // not {image}: clang reads that as a copy of image, GCC as an array
        g["textures"] = {{{"source", 0}}};
        g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
        g["meshes"][0]["primitives"][0]["material"] = 0;
    });
}

std::string glb_header(std::uint32_t total, std::uint32_t chunk_length) {
    std::string b = "glTF";
    for (std::uint32_t v : {2u, total, chunk_length}) {
        for (int i = 0; i < 4; ++i) b += char((v >> (8 * i)) & 0xff);
    }
    return b + "JSON" + "{}  ";
}

const std::vector<GltfCase>& gltf_cases() {
    static const std::vector<GltfCase> cases = {
        {"missing file", [](Model&) {}, {"model.gltf\" does not exist"}},
        {"a folder as the model", [](Model& m) { fs::create_directory(m.path); }, {"is not a regular file"}},
        {"empty file", text(""), {"the file is empty"}},
        {"not glTF: PNG bytes", text(png_header(1, 1)), {"not a glTF file", "89 50 4E 47"}},
        {"not glTF: JSON array", text("[{}]"), {"not a glTF file"}},
        {"not glTF: text", text("hello"), {"not a glTF file", "68 65 6C 6C"}},
        {"truncated JSON", text("{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{"), {"invalid JSON"}},
        {"deep nesting", text("{\"extras\": " + std::string(5000, '[') + std::string(5000, ']') + "}"),
         {"JSON nesting depth exceeds 64"}},
        {"accessor index out of range", edit([](Json& g) { g["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9; }),
         {"POSITION of mesh 0 primitive 0 uses accessor 9 but the file has 2 accessors"}},
        {"accessor count past its bufferView", edit([](Json& g) { g["accessors"][1]["count"] = 4; }),
         {"accessor 1 (POSITION of mesh 0 primitive 0)", "bufferView 1 which has 36 bytes"}},
        {"accessor count 2^32 - 1", edit([](Json& g) { g["accessors"][1]["count"] = 4294967295u; }),
         {"accessor 1 (POSITION of mesh 0 primitive 0) has count 4294967295"}},
        {"bufferView past the buffer", edit([](Json& g) { g["bufferViews"][1]["byteLength"] = 1 << 30; }),
         {"bufferView 1 covers bytes [8, 1073741832) of buffer 0 which has 44 bytes"}},
        {"index past the vertices", edit([](Json& g) {
             std::string bytes(reinterpret_cast<const char*>(fuzz_layout::kTriangle), sizeof fuzz_layout::kTriangle);
             bytes[4] = 7; // indices 0, 1, 7 of 3 vertices
             g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bytes);
         }), {"indices of mesh 0 primitive 0 (accessor 0) has value 7 at position 2 but the primitive has 3 vertices"}},
        {"uri \"..\"", edit([](Json& g) { g["buffers"][0]["uri"] = "../secret.bin"; }),
         {"buffer 0 uri \"../secret.bin\"", "outside the model folder"}},
        {"uri absolute", edit([](Json& g) { g["buffers"][0]["uri"] = "/etc/passwd"; }),
         {"buffer 0 uri \"/etc/passwd\"", "is an absolute path"}},
        {"uri naming a FIFO", [](Model& m) {
             REQUIRE(::mkfifo((m.dir / "pipe.bin").c_str(), 0600) == 0);
             edit([](Json& g) { g["buffers"][0]["uri"] = "pipe.bin"; })(m);
         }, {"pipe.bin\"", "is not a regular file"}},
        {"uri symlink leading out", [](Model& m) {
             fs::create_directory(m.dir / "inner");
             support::write_file(m.dir / "secret.bin", std::string(44, '\0'));
             fs::create_symlink(m.dir / "secret.bin", m.dir / "inner" / "link.bin");
             m.path = (m.dir / "inner" / "model.gltf").string();
             edit([](Json& g) { g["buffers"][0]["uri"] = "link.bin"; })(m);
         }, {"link.bin\" resolves to", "outside the model folder"}},
        {"huge image (10000 x 10000 header)",
         with_image({{"uri", "data:image/png;base64," + base64(png_header(10000, 10000))}}),
         {"image 0: image is 10000 x 10000 pixels, the limit is 67108864 pixels"}},
        {"huge image (100000 x 100000 header, beyond stb_image)",
         with_image({{"uri", "data:image/png;base64," + base64(png_header(100000, 100000))}}),
         {"image 0: cannot decode the image header"}},
        {"image over a small pixel limit", [](Model& m) {
             m.options.max_image_pixels = 3;
             with_image({{"uri", "data:image/png;base64," + base64(png_header(2, 2))}})(m);
         }, {"image 0: image is 2 x 2 pixels, the limit is 3 pixels"}},
        {"image bytes that are no image", with_image({{"uri", "data:image/png;base64," + base64("not an image")}}),
         {"image 0: the image is neither PNG nor JPEG (first bytes 6E 6F 74)"}},
        {"camera yfov 0", edit([](Json& g) {
             g["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0}, {"znear", 0.1}}}}};
             g["nodes"][0]["camera"] = 0;
         }), {"camera 0 yfov 0 rad is not in (0, pi)"}},
        // Finite as a double (tinygltf), infinite as the float of scene::Instance.
        {"node translation 1e39", edit([](Json& g) { g["nodes"][0]["translation"] = {1e39, 0, 0}; }),
         {"node 0 has a world transform too large for single precision"}},
        {"node is its own child", edit([](Json& g) { g["nodes"][0]["children"] = {0}; }),
         {"the node graph has a cycle of 1 node (parent -> child): 0 -> 0"}},
        {"GLB chunk length 2^32 - 1", text(glb_header(24, 0xffffffffu)), {"GLB chunk 0 length 4294967295"}},
        {"GLB length field 0", text(glb_header(0, 4)), {"GLB header length 0", "does not match the file size"}},
        {"file over the size limit", [](Model& m) {
             m.options.max_file_bytes = 64;
             edit([](Json&) {})(m);
         }, {"more than the limit of 64"}},
    };
    return cases;
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("glTF: every broken file is refused with the file and the broken rule") {
    support::for_each_case(gltf_cases(), 20, [](const GltfCase& c) {
        Model model;
        c.make(model);
        const rob::Isolated load = rob::isolated([&model] {
            const frustum::Result<scene::Scene> result = scene::load_gltf(model.path, model.options);
            return result.ok() ? std::string("loaded") : "error: " + result.error();
        });
        CHECK_MESSAGE(load.finished, "load_gltf() did not return: ", load.how);
        CHECK_MESSAGE(load.value.rfind("error: ", 0) == 0, "the file was accepted");
        if (load.value.rfind("error: ", 0) != 0) return;
        support::check_message(load.value.substr(7), "scene::load_gltf(): " + model.path + ": ", c.phrases, true);
    });
}

} // TEST_SUITE
#endif
