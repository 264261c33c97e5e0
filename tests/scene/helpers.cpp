#include "helpers.hpp"

#include <fstream>
#include <iterator>
#include <stdexcept>

namespace scene_test {

namespace fs = std::filesystem;

std::string model_path(const std::string& name) {
    return std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-models/" + name;
}

std::string showcase_path() { return std::string(FRUSTUM_SOURCE_DIR) + "/assets/showcase.gltf"; }

Bytes read_bytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot read " + path.string());
    return Bytes(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

void write_bytes(const fs::path& path, const Bytes& bytes) {
    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!file) throw std::runtime_error("cannot write " + path.string());
}

void write_text(const fs::path& path, const std::string& text) {
    write_bytes(path, Bytes(text.begin(), text.end()));
}

Json read_json(const fs::path& path) {
    Bytes bytes = read_bytes(path);
    return Json::parse(bytes.begin(), bytes.end());
}

namespace {
const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
const char kDataPrefix[] = "data:application/octet-stream;base64,";
} // namespace

Bytes base64_decode(const std::string& text) {
    Bytes out;
    std::uint32_t bits = 0;
    int count = 0;
    for (char c : text) {
        const char* at = std::char_traits<char>::find(kAlphabet, 64, c);
        if (!at) continue; // '=' padding
        bits = bits << 6 | std::uint32_t(at - kAlphabet);
        if ((count += 6) >= 8) {
            count -= 8;
            out.push_back(std::uint8_t(bits >> count));
        }
    }
    return out;
}

std::string base64_encode(const Bytes& bytes) {
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t chunk = std::uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) chunk |= std::uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) chunk |= bytes[i + 2];
        out += kAlphabet[chunk >> 18 & 63];
        out += kAlphabet[chunk >> 12 & 63];
        out += i + 1 < bytes.size() ? kAlphabet[chunk >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
    }
    return out;
}

Bytes buffer0(const Json& gltf) {
    const std::string uri = gltf["buffers"][0]["uri"];
    return base64_decode(uri.substr(uri.find(',') + 1));
}

void set_buffer0(Json& gltf, const Bytes& bytes) {
    gltf["buffers"][0]["uri"] = kDataPrefix + base64_encode(bytes);
    gltf["buffers"][0]["byteLength"] = bytes.size();
}

void image0_into_buffer_view(Json& gltf) {
    Bytes buffer = buffer0(gltf);
    while (buffer.size() % 4) buffer.push_back(0);
    const std::string uri = gltf["images"][0]["uri"];
    const Bytes png = base64_decode(uri.substr(uri.find(',') + 1));
    gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", png.size()}});
    buffer.insert(buffer.end(), png.begin(), png.end());
    set_buffer0(gltf, buffer);
    gltf["images"][0] = {{"bufferView", gltf["bufferViews"].size() - 1}, {"mimeType", "image/png"}};
}

Bytes make_glb(Json gltf, const Bytes& bin) {
    gltf["buffers"][0].erase("uri");
    gltf["buffers"][0]["byteLength"] = bin.size();
    std::string json = gltf.dump();
    while (json.size() % 4) json += ' ';
    Bytes padded_bin = bin;
    while (padded_bin.size() % 4) padded_bin.push_back(0);
    auto put_u32 = [](Bytes& out, std::uint32_t value) {
        for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(value >> (8 * i)));
    };
    Bytes glb = {'g', 'l', 'T', 'F'};
    put_u32(glb, 2);
    put_u32(glb, std::uint32_t(12 + 8 + json.size() + 8 + padded_bin.size()));
    put_u32(glb, std::uint32_t(json.size()));
    put_u32(glb, 0x4E4F534A);
    glb.insert(glb.end(), json.begin(), json.end());
    put_u32(glb, std::uint32_t(padded_bin.size()));
    put_u32(glb, 0x004E4942);
    glb.insert(glb.end(), padded_bin.begin(), padded_bin.end());
    return glb;
}

TempDir::TempDir() : model_dir_(root_ / "model"), outside_dir_(root_ / "outside") {
    fs::create_directories(model_dir_);
    fs::create_directories(outside_dir_);
}

} // namespace scene_test
