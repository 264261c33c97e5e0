// Shortest round-trip text of a float or double in std::to_chars's format,
// built from snprintf and strtod/strtof only: for standard libraries that
// declare but do not implement floating-point std::to_chars (libc++ 13, as
// emscripten 3.1 ships it). tests/math/shortest_text_test.cpp checks that it
// gives exactly std::to_chars's text wherever that exists.
//
// std::to_chars(first, last, value) writes the fewest significant digits that
// read back as `value` (the closest such digits when there is a choice), in
// fixed or scientific form, whichever is shorter (fixed on a tie):
//   100 -> "100", 1e+20 -> "1e+20", 0.001 -> "0.001", 1e-05 -> "1e-05".
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>

namespace frustum::detail {

namespace shortest {

// A decimal  d.ddd * 10^exponent  with `count` significant digits held as
// the integer `digits` (count <= 17, so it fits in 64 bits).
struct Decimal {
    std::uint64_t digits;
    int count;
    int exponent;
};

inline std::uint64_t power_of_ten(int n) {
    std::uint64_t p = 1;
    while (n-- > 0) p *= 10;
    return p;
}

inline std::string digit_string(const Decimal& d) {
    std::string s = std::to_string(d.digits);
    return std::string(static_cast<std::size_t>(d.count) - s.size(), '0') + s;
}

// "d.ddde+XX", a form strtod reads.
inline std::string scientific(const Decimal& d) {
    const std::string s = digit_string(d);
    std::string out(1, s[0]);
    if (s.size() > 1) out += "." + s.substr(1);
    char exponent[16];
    std::snprintf(exponent, sizeof exponent, "e%c%02d", d.exponent < 0 ? '-' : '+', std::abs(d.exponent));
    return out + exponent;
}

// Fixed form; a whole number is written exactly (as std::to_chars does:
// 397605984.f is "397605984", not its shortest digits padded, "397605980").
inline std::string fixed(const Decimal& d, double magnitude) {
    const std::string s = digit_string(d);
    const int n = d.count;
    if (d.exponent >= n - 1) {
        char whole[400]; // DBL_MAX has 309 digits
        std::snprintf(whole, sizeof whole, "%.0f", magnitude);
        return whole;
    }
    if (d.exponent >= 0) {
        const std::size_t point = static_cast<std::size_t>(d.exponent) + 1;
        return s.substr(0, point) + "." + s.substr(point);
    }
    return "0." + std::string(static_cast<std::size_t>(-d.exponent - 1), '0') + s;
}

template <class T>
bool reads_back(const std::string& text, T magnitude) {
    if constexpr (std::is_same_v<T, float>) {
        return std::strtof(text.c_str(), nullptr) == magnitude;
    } else {
        return std::strtod(text.c_str(), nullptr) == magnitude;
    }
}

// The neighbour one unit up or down in the last digit, keeping `count` digits.
inline Decimal step(Decimal d, int direction) {
    const std::uint64_t low = power_of_ten(d.count - 1), high = power_of_ten(d.count);
    if (direction > 0) {
        if (++d.digits == high) d.digits = low, ++d.exponent;
    } else {
        if (d.digits-- == low) d.digits = high - 1, --d.exponent;
    }
    return d;
}

} // namespace shortest

template <class T>
std::string shortest_text_portable(T value) {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>, "float or double");
    const std::string sign = std::signbit(value) ? "-" : "";
    if (std::isnan(value)) return sign + "nan";
    if (std::isinf(value)) return sign + "inf";
    if (value == T(0)) return sign + "0";
    const T magnitude = std::abs(value);
    const int max_count = std::is_same_v<T, float> ? 9 : 17; // always enough to round-trip
    shortest::Decimal found{0, 0, 0};
    for (int count = 1; count <= max_count && found.count == 0; ++count) {
        // The closest decimal with `count` digits (printf rounds exactly).
        char text[64];
        std::snprintf(text, sizeof text, "%.*e", count - 1, static_cast<double>(magnitude));
        const char* e = std::strchr(text, 'e');
        shortest::Decimal d{0, count, std::atoi(e + 1)};
        for (const char* c = text; c < e; ++c) {
            if (*c != '.') d.digits = d.digits * 10 + static_cast<std::uint64_t>(*c - '0');
        }
        if (shortest::reads_back(text, magnitude)) {
            found = d;
        } else {
            // Next to a power of two the round-trip interval is lopsided: the
            // closest decimal may miss it while its neighbour on the other
            // side of the value still reads back.
            for (const int direction : {1, -1}) {
                const shortest::Decimal n = shortest::step(d, direction);
                if (found.count == 0 && shortest::reads_back(shortest::scientific(n), magnitude)) found = n;
            }
        }
    }
    while (found.count > 1 && found.digits % 10 == 0) found.digits /= 10, --found.count;
    const std::string f = shortest::fixed(found, static_cast<double>(magnitude)), s = shortest::scientific(found);
    return sign + (f.size() <= s.size() ? f : s);
}

} // namespace frustum::detail
