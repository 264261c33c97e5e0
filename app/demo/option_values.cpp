#include "demo/option_values.hpp"

#include <charconv>

namespace demo {

std::optional<int> parse_count(std::string_view text, int max) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 1 || value > max) {
        return std::nullopt;
    }
    return value;
}

std::optional<std::pair<int, int>> parse_pair(std::string_view text, int max) {
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos) {
        return std::nullopt;
    }
    const auto first = parse_count(text.substr(0, x), max);
    const auto second = parse_count(text.substr(x + 1), max);
    if (!first || !second) {
        return std::nullopt;
    }
    return std::pair<int, int>(*first, *second);
}

std::string default_scene() { return std::string(FRUSTUM_ASSETS_DIR) + "/showcase.gltf"; }

} // namespace demo
