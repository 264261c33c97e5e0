#include "uri_check.hpp"

#include "budget_check.hpp"
#include "extensions.hpp"
#include "foreign_message.hpp"

#include "scene/load_gltf.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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

// JSON events -> the checks of check_json_and_uris(). Depth 0 is the root,
// 1 a root member ("buffers"), 2 an element of it, 3 a member of that.
class UriSax : public nlohmann::json_sax<nlohmann::json> {
public:
    explicit UriSax(const Budget& budget)
        : max_values_(budget.max_decoded_bytes / kJsonValueBytes), max_nodes_(budget.max_nodes),
          budget_note_(" the budget of " + format_bytes(budget.max_decoded_bytes) +
                       " (raise it with --max-memory-mb)") {}

    bool null() override { return value(Kind::Other); }
    bool boolean(bool) override { return value(Kind::Other); }
    bool number_integer(number_integer_t number) override {
        if (number < 0 && stack_.size() >= 3 && stack_.back() == Kind::Object &&
            (key_ == "byteOffset" || key_ == "byteLength" || key_ == "byteStride" ||
             key_ == "count")) {
            return fail(root_key_ + "[" + std::to_string(item_) + "] has " + key_ + " " +
                        std::to_string(number) + ", expected >= 0");
        }
        return value(Kind::Other);
    }
    bool number_unsigned(number_unsigned_t) override { return value(Kind::Other); }
    bool number_float(number_float_t, const string_t&) override { return value(Kind::Other); }
    bool string(string_t& text) override { return value(Kind::String, &text); }
    bool binary(binary_t&) override { return value(Kind::Other); }
    bool start_object(std::size_t) override { return open(Kind::Object); }
    bool start_array(std::size_t) override { return open(Kind::Array); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(string_t& name) override {
        key_ = name;
        if (stack_.size() == 1) {
            root_key_ = name;
            list_ = name == "buffers" ? "buffer" : name == "images" ? "image" : nullptr;
            item_ = -1;
        } else if (stack_.size() == 3) {
            uri_key_ = name == "uri";
            if (root_key_ == "skins" && name == "inverseBindMatrices") {
                skin_has_matrices_ = true;
            }
        } else if (stack_.size() == 6 && in_target_ && name == "node") {
            target_has_node_ = true;
        }
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
        problem_ = "invalid JSON: " + foreign_message(error.what());
        return false;
    }

    const std::string& problem() const { return problem_; }
    // A skin without inverseBindMatrices or an animation channel target
    // without node (both valid glTF 2.0) was read: tinygltf 2.7 refuses them.
    bool tinygltf_refuses_ignored_parts() const { return refused_ignored_part_; }
    // The root's extensionsRequired as read ({} when absent), for check_required_extensions().
    nlohmann::json required_extensions() const {
        nlohmann::json root = nlohmann::json::object();
        if (required_is_array_.value_or(false)) {
            root["extensionsRequired"] = required_;
        } else if (required_is_array_.has_value()) {
            root["extensionsRequired"] = nullptr;
        }
        return root;
    }

private:
    enum class Kind { Object, Array, String, Other };

    bool open(Kind kind) {
        if (!value(kind)) {
            return false;
        }
        if (kind == Kind::Object && root_key_ == "skins" && stack_.size() == 2) {
            skin_has_matrices_ = false; // skins[i] starts
        }
        if (kind == Kind::Object && root_key_ == "animations" && stack_.size() == 5 &&
            key_ == "target") {
            in_target_ = true; // animations[i].channels[j].target starts
            target_has_node_ = false;
        }
        stack_.push_back(kind);
        return true;
    }
    bool close() {
        if (root_key_ == "skins" && stack_.size() == 3 && !skin_has_matrices_) {
            refused_ignored_part_ = true;
        }
        if (in_target_ && stack_.size() == 6) {
            in_target_ = false;
            refused_ignored_part_ = refused_ignored_part_ || !target_has_node_;
        }
        stack_.pop_back();
        if (stack_.size() == 1) {
            list_ = nullptr; // the end of "buffers" or "images"
        }
        return true;
    }
    bool fail(std::string message) {
        problem_ = std::move(message);
        return false;
    }
    bool value(Kind kind, const std::string* text = nullptr) {
        if (++values_ > max_values_) {
            return fail("the JSON holds more than " + std::to_string(max_values_) +
                        " values, whose parsed tree (" + std::to_string(kJsonValueBytes) +
                        " B per value) would be over" + budget_note_);
        }
        const std::size_t depth = stack_.size();
        if (depth == 0 && kind != Kind::Object) {
            return fail("the JSON root is not an object");
        }
        if (root_key_ == "extensionsRequired" && depth >= 1) {
            // Collected here, checked by check_required_extensions() once
            // the stream ends (an array of strings; anything else is refused there).
            if (depth == 1) {
                required_is_array_ = kind == Kind::Array;
            } else if (depth == 2) {
                required_.push_back(kind == Kind::String && text ? nlohmann::json(*text)
                                                                 : nlohmann::json(nullptr));
            }
        }
        if (depth == 2 && stack_[1] == Kind::Array) {
            ++item_;
            if (root_key_ == "nodes" && std::uint64_t(item_) >= max_nodes_) {
                return fail("the file has more than " + std::to_string(max_nodes_) +
                            " nodes, over the limit of " + std::to_string(max_nodes_) +
                            " (raise it with --max-nodes)");
            }
        }
        const bool in_list = list_ != nullptr && depth >= 2 && stack_[1] == Kind::Array;
        if (in_list && depth == 2) {
            if (kind != Kind::Object) {
                return fail(name() + " is not a JSON object");
            }
        }
        if (in_list && depth == 3 && uri_key_) {
            uri_key_ = false;
            if (kind != Kind::String) {
                return fail(name() + " uri is not a string");
            }
            if (std::string problem = uri_problem(*text); !problem.empty()) {
                return fail(name() + " uri \"" + *text + "\" " + problem);
            }
        }
        return true;
    }
    std::string name() const { return std::string(list_) + " " + std::to_string(item_); }

    std::uint64_t max_values_;
    std::uint64_t max_nodes_;
    std::string budget_note_;
    std::uint64_t values_ = 0;
    std::vector<Kind> stack_;
    std::string key_;      // the last member name read
    std::string root_key_; // the root member being read ("accessors")
    const char* list_ = nullptr; // "buffer" or "image" while inside that array
    long long item_ = -1;
    bool uri_key_ = false;
    std::string problem_;
    bool skin_has_matrices_ = false;   // in skins[i]: its inverseBindMatrices was read
    bool in_target_ = false;           // in animations[i].channels[j].target
    bool target_has_node_ = false;     // its node was read
    bool refused_ignored_part_ = false;
    std::optional<bool> required_is_array_; // set when the root has extensionsRequired
    nlohmann::json required_ = nlohmann::json::array();
};

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

frustum::Result<JsonFacts> check_json_and_uris(const char* text, std::size_t size_bytes,
                                               const Budget& budget) {
    UriSax events(budget);
    bool parsed = false;
    try {
        parsed = nlohmann::json::sax_parse(text, text + size_bytes, &events);
    } catch (const nlohmann::json::exception& error) {
        return frustum::Error{"invalid JSON: " + foreign_message(error.what())};
    }
    if (!parsed) {
        return frustum::Error{events.problem().empty() ? "invalid JSON" : events.problem()};
    }
    if (frustum::Status supported = check_required_extensions(events.required_extensions());
        !supported) {
        return frustum::Error{supported.error()};
    }
    return JsonFacts{events.tinygltf_refuses_ignored_parts()};
}

} // namespace scene::detail
