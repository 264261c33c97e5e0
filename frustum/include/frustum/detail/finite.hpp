// Finiteness of the library's vector types: the one helper every input
// check uses (no NaN, no infinity in any component).
#pragma once

#include "frustum/types.hpp"

#include <cmath>

namespace frustum::detail {

// A scalar: neither NaN nor infinite.
template <class T>
bool finite(T v) {
    return std::isfinite(v);
}

template <class T>
bool finite3(const Vec3<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

template <class T>
bool finite4(const Vec4<T>& v) {
    return finite3(Vec3<T>(v)) && std::isfinite(v.w);
}

} // namespace frustum::detail
