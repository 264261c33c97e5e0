// Lets doctest print image::Rgba values in failed checks.
#pragma once

#include <doctest/doctest.h>
#include <image/image.hpp>

#include <sstream>

namespace doctest {
template <>
struct StringMaker<image::Rgba> {
    static String convert(const image::Rgba& c) {
        std::ostringstream out;
        out << "rgba(" << int{c[0]} << ", " << int{c[1]} << ", " << int{c[2]} << ", " << int{c[3]} << ")";
        return out.str().c_str();
    }
};
} // namespace doctest
