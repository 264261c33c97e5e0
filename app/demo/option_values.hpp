// Values shared by the commands' option parsers (render, window, reports).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace demo {

// A decimal count in [1, max], the whole text; empty otherwise.
std::optional<int> parse_count(std::string_view text, int max);

// "640x360" -> (640, 360): two counts in [1, max] joined by 'x'.
std::optional<std::pair<int, int>> parse_pair(std::string_view text, int max);

// The showcase scene in FRUSTUM_ASSETS_DIR (compiled in at build time).
std::string default_scene();

} // namespace demo
