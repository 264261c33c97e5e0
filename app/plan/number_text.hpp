// Numbers in messages and labels: up to three significant digits ("2",
// "0.25", "3.99", "1.2e+03"). Header-only.
#pragma once

#include <cstdio>
#include <string>

namespace render {

inline std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

} // namespace render
