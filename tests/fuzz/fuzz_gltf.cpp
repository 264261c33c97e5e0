// libFuzzer target: arbitrary bytes as a .gltf/.glb file -> scene::load_gltf.
//
// app/scene only loads from a path (its in-memory parse is internal), so
// each input is written to <private temp dir>/model/model.gltf (the loader
// tells GLB from JSON by the magic, not the name), next to the files laid
// out by gltf_layout.hpp (buffers, an image, a folder, a FIFO, a symlink
// leading out; a timeout means a FIFO was opened, a marker vertex in the
// scene means a file outside the folder was read).
//
// Besides "no crash" (ASan + UBSan abort on memory and UB errors), every
// result is checked against load_gltf.hpp / scene.hpp: a failure is one line
// "scene::load_gltf(): <path>: <reason>"; a success has every index in
// bounds, every size consistent and every transform finite.
#include "gltf_layout.hpp"
#include "scene/load_gltf.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

fs::path g_root;      // <tmp>/frustum-fuzz-gltf-XXXXXX
std::string g_model; // g_root/model/model.gltf

[[noreturn]] void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_gltf: contract violation: %s\n  %s\n", what, detail.c_str());
    std::abort();
}

void make_layout() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/frustum-fuzz-gltf-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) {
        std::perror("fuzz_gltf: mkdtemp");
        std::exit(1);
    }
    g_root = pattern;
    g_model = fuzz_layout::make(g_root);
    if (g_model.empty()) {
        std::fprintf(stderr, "fuzz_gltf: cannot lay out %s\n", g_root.c_str());
        std::exit(1);
    }
    std::atexit([] {
        std::error_code ignored;
        fs::remove_all(g_root, ignored);
    });
}

template <int C, int R>
bool finite(const glm::mat<C, R, float>& m) {
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

void check_scene(const scene::Scene& s) {
    const auto bad = [](bool broken, const char* what) {
        if (broken) fail("loaded scene breaks scene.hpp", what);
    };
    for (const image::Image& image : s.images) {
        bad(image.width <= 0 || image.height <= 0, "image size <= 0");
        bad(image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4, "image rgba size");
    }
    for (const scene::Material& m : s.materials) {
        bad(m.base_color_texture < -1 || m.base_color_texture >= int(s.images.size()), "material texture index");
    }
    for (const scene::Mesh& mesh : s.meshes) {
        for (const scene::Primitive& p : mesh.primitives) {
            const std::size_t n = p.positions.size();
            bad(!p.normals.empty() && p.normals.size() != n, "normals count");
            bad(!p.colors.empty() && p.colors.size() != n, "colors count");
            bad(!p.texcoords.empty() && p.texcoords.size() != n, "texcoords count");
            bad(p.material < -1 || p.material >= int(s.materials.size()), "primitive material index");
            bad(std::uint32_t(p.mode) > 6, "primitive mode");
            for (std::uint32_t index : p.indices) bad(index >= n, "vertex index out of range");
            for (const auto& v : p.positions) bad(v.x == fuzz_layout::kOutsideMarker, "read ../outside.bin (sandbox escape)");
        }
    }
    for (const scene::Instance& instance : s.instances) {
        bad(instance.mesh < 0 || instance.mesh >= int(s.meshes.size()), "instance mesh index");
        bad(!finite(instance.world), "instance world transform not finite");
    }
    for (const scene::Camera& camera : s.cameras) {
        bad(!finite(camera.camera_to_world), "camera transform not finite");
    }
    if (!s.instances.empty()) {
        bad(!finite(glm::mat2x3(s.world_bounds.min, s.world_bounds.max)), "world bounds not finite");
    }
    if (s.mirror) bad(s.mirror->instance < -1 || s.mirror->instance >= int(s.instances.size()), "mirror instance");
    if (s.lens) bad(s.lens->instance < -1 || s.lens->instance >= int(s.instances.size()), "lens instance");
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    make_layout();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (!fuzz_layout::write_file(g_model, data, size)) {
        std::fprintf(stderr, "fuzz_gltf: cannot write %s\n", g_model.c_str());
        std::exit(1);
    }
    const frustum::Result<scene::Scene> result = scene::load_gltf(g_model);
    if (result.ok()) {
        check_scene(*result);
        return 0;
    }
    const std::string& message = result.error();
    const std::string prefix = "scene::load_gltf(): " + g_model + ": ";
    if (message.rfind(prefix, 0) != 0 || message.size() == prefix.size()) {
        fail("error does not start with \"scene::load_gltf(): <path>: \"", message);
    }
    if (message.find('\n') != std::string::npos) {
        fail("error is not one line", message); // e.g. regressions/gltf/uri-with-newline.gltf
    }
    return 0;
}
