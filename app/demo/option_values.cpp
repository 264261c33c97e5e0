#include "demo/option_values.hpp"

#include <charconv>
#include <cmath>

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

std::optional<float> parse_number(std::string_view text) {
    float value = 0.0f;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

std::optional<std::vector<float>> parse_numbers(std::string_view text, std::size_t count) {
    std::vector<float> values;
    for (;;) {
        const std::size_t comma = text.find(',');
        const auto value = parse_number(text.substr(0, comma));
        if (!value) {
            return std::nullopt;
        }
        values.push_back(*value);
        if (comma == std::string_view::npos) {
            break;
        }
        text.remove_prefix(comma + 1);
    }
    if (values.size() != count) {
        return std::nullopt;
    }
    return values;
}

std::string default_scene() { return std::string(FRUSTUM_ASSETS_DIR) + "/showcase.gltf"; }

} // namespace demo
