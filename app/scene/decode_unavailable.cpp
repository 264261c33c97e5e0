// The web page's build (emscripten) in place of decode_draco.cpp and
// decode_meshopt.cpp: Debian's libdraco and libmeshoptimizer are native
// libraries, so the page refuses compressed data by name (the scene it
// embeds, assets/showcase.gltf, has none; docs/web.md).
#include "decompress.hpp"

#include "extensions.hpp"

#include <string>

namespace scene::detail {
namespace {

frustum::Error unavailable(const std::string& where, const char* extension, const char* library) {
    return frustum::Error{where + " " + extension + ": not decoded in the web page's build (no " + library +
                          " for WebAssembly)"};
}

} // namespace

frustum::Status decode_meshopt(tinygltf::Model& model) {
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        if (model.bufferViews[v].extensions.count(kMeshopt) != 0) {
            return unavailable("bufferView " + std::to_string(v), kMeshopt, "libmeshoptimizer");
        }
    }
    return {};
}

frustum::Status decode_draco(tinygltf::Model& model, std::uint64_t) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            if (model.meshes[m].primitives[p].extensions.count(kDraco) != 0) {
                return unavailable("mesh " + std::to_string(m) + " primitive " + std::to_string(p), kDraco, "libdraco");
            }
        }
    }
    return {};
}

} // namespace scene::detail
