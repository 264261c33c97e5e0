#include "uri_check.hpp"

#include "extensions.hpp"
#include "foreign_message.hpp"

#include <nlohmann/json.hpp>

#include <cctype>

namespace scene::detail {

namespace {

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// As tinygltf does before opening the file: "%XY" -> byte, rest unchanged.
std::string percent_decode(const std::string& uri) {
    std::string decoded;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex_value(uri[i + 1]) >= 0 &&
            hex_value(uri[i + 2]) >= 0) {
            decoded += static_cast<char>(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    return decoded;
}

bool has_scheme(const std::string& uri) {
    std::size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0 || uri.find('/') < colon) {
        return false;
    }
    for (std::size_t i = 0; i < colon; ++i) {
        const unsigned char c = static_cast<unsigned char>(uri[i]);
        if (!(std::isalnum(c) || c == '+' || c == '-' || c == '.')) {
            return false;
        }
    }
    return std::isalpha(static_cast<unsigned char>(uri[0])) != 0;
}

frustum::Status check_uris_of(const nlohmann::json& root, const char* array_name,
                              const char* item_name) {
    auto array = root.find(array_name);
    if (array == root.end() || !array->is_array()) {
        return {};
    }
    for (std::size_t i = 0; i < array->size(); ++i) {
        const nlohmann::json& item = (*array)[i];
        const std::string name = std::string(item_name) + " " + std::to_string(i);
        if (!item.is_object()) {
            return frustum::Error{name + " is not a JSON object"};
        }
        auto uri = item.find("uri");
        if (uri == item.end()) {
            continue;
        }
        if (!uri->is_string()) {
            return frustum::Error{name + " uri is not a string"};
        }
        const std::string& text = uri->get_ref<const std::string&>();
        if (std::string problem = uri_problem(text); !problem.empty()) {
            return frustum::Error{name + " uri \"" + text + "\" " + problem};
        }
    }
    return {};
}

} // namespace

std::string uri_problem(const std::string& uri) {
    if (uri.compare(0, 5, "data:") == 0) {
        return uri.find(";base64,") == std::string::npos ? "is a data uri without \";base64,\""
                                                         : std::string();
    }
    const std::string path = percent_decode(uri);
    if (path.empty()) {
        return "is empty";
    }
    if (path.find('\0') != std::string::npos) {
        return "contains a NUL byte";
    }
    if (path.find('\\') != std::string::npos) {
        return "contains a backslash (uris separate folders with '/')";
    }
    if (path.front() == '/') {
        return "is an absolute path, outside the model folder";
    }
    if (has_scheme(path)) {
        return "is not a relative file path (it has a scheme)";
    }
    std::size_t begin = 0;
    while (true) {
        const std::size_t end = path.find('/', begin);
        const std::string segment = path.substr(begin, end == std::string::npos ? end : end - begin);
        if (segment == "..") {
            return "uses \"..\", which leads outside the model folder";
        }
        if (end == std::string::npos) {
            if (segment.empty() || segment == ".") {
                return "names a folder, not a file";
            }
            return {};
        }
        begin = end + 1;
    }
}

frustum::Status check_json_and_uris(const char* text, std::size_t size_bytes) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(text, text + size_bytes);
    } catch (const nlohmann::json::exception& error) {
        return frustum::Error{"invalid JSON: " + foreign_message(error.what())};
    }
    if (!root.is_object()) {
        return frustum::Error{"the JSON root is not an object"};
    }
    if (frustum::Status status = check_required_extensions(root); !status) {
        return status;
    }
    if (frustum::Status status = check_uris_of(root, "buffers", "buffer"); !status) {
        return status;
    }
    return check_uris_of(root, "images", "image");
}

} // namespace scene::detail
