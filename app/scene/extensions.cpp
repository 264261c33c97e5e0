#include "extensions.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace scene::detail {

const std::vector<std::string>& supported_extensions() {
    static const std::vector<std::string> names = {kGpuInstancing, kMeshopt, kDraco, kUnlit, kMeshQuantization, kTextureTransform};
    return names;
}

frustum::Status check_required_extensions(const nlohmann::json& root) {
    auto required = root.find("extensionsRequired");
    if (required == root.end()) {
        return {};
    }
    if (!required->is_array()) {
        return frustum::Error{"extensionsRequired is not an array"};
    }
    const std::vector<std::string>& supported = supported_extensions();
    for (std::size_t i = 0; i < required->size(); ++i) {
        const nlohmann::json& name = (*required)[i];
        if (!name.is_string()) {
            return frustum::Error{"extensionsRequired[" + std::to_string(i) + "] is not a string"};
        }
        const std::string& text = name.get_ref<const std::string&>();
        if (std::find(supported.begin(), supported.end(), text) == supported.end()) {
            std::string list;
            for (const std::string& known : supported) {
                list += (list.empty() ? "" : ", ") + known;
            }
            return frustum::Error{"the file requires glTF extension " + text + ", which is not supported (supported: " +
                                  list + ")"};
        }
    }
    return {};
}

} // namespace scene::detail
