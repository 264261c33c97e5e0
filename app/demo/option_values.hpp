// Values shared by the commands' option parsers (render, window, reports).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace demo {

// A decimal count in [1, max], the whole text; empty otherwise.
std::optional<int> parse_count(std::string_view text, int max);

// "640x360" -> (640, 360): two counts in [1, max] joined by 'x'.
std::optional<std::pair<int, int>> parse_pair(std::string_view text, int max);

// --msaa N of render and window: parse_count(text, kMaxMsaaOption); the
// context's own maximum (GL_MAX_SAMPLES) is checked once it exists.
inline constexpr int kMaxMsaaOption = 64;
inline constexpr const char* kMsaaExpected = "--msaa must be a sample count in 1..64 (1 = off), got ";

// A finite decimal number, the whole text; empty otherwise.
std::optional<float> parse_number(std::string_view text);

// Exactly `count` finite numbers separated by commas ("1,0,-2.5").
std::optional<std::vector<float>> parse_numbers(std::string_view text, std::size_t count);

// The showcase scene in FRUSTUM_ASSETS_DIR (compiled in at build time).
std::string default_scene();

} // namespace demo
