// Numbers in messages and labels: up to three significant digits ("2",
// "0.25", "3.99", "1.2e+03"). Header-only.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace plan {

inline std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

// As number_text(), but "0" for a value within rounding of zero at the size
// of the numbers it stands among: |value| < kZeroFraction * |scale| (a lens
// centre computed in float as 2.23e-08 of the frame's half width is "0").
inline constexpr double kZeroFraction = 1e-4;
inline std::string number_text(double value, double scale) {
    return number_text(std::abs(value) < kZeroFraction * std::abs(scale) ? 0.0 : value);
}

} // namespace plan
