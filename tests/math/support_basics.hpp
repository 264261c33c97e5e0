// Basics of the math suite shared by its helper headers: the names every
// test uses, the depth ranges, pi, eps and the sanitizer switch.
//
// Conventions used by every test (see frustum/include/frustum/*.hpp):
// column vectors, clip = M * world; a MatrixPair is scaled so that w > 0
// inside; planes are inward-positive.
#pragma once

#include <doctest/doctest.h>
#include <frustum/frustum.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

// Set when built with -DFRUSTUM_SANITIZE=ON (ASan + UBSan, which traps a
// float division by zero): the few inputs that make the library divide by
// zero are then left out, so one known problem cannot abort the suite.
#if defined(FRUSTUM_SANITIZED)
#define MTEST_SANITIZED 1
#else
#define MTEST_SANITIZED 0
#endif

namespace mtest {

using frustum::DepthRange;
using frustum::Mat4;
using frustum::MatrixPair;
using frustum::Plane;
using frustum::Vec3;
using frustum::Vec4;

constexpr DepthRange all_depth_ranges[3] = {DepthRange::ZeroToOne, DepthRange::MinusOneToOne,
                                            DepthRange::ReversedZeroToOne};

constexpr double pi = 3.14159265358979323846;

template <class T>
constexpr T eps() {
    return std::numeric_limits<T>::epsilon();
}

// Runs check(depth) once per depth range, the range's name INFO'd.
template <class Check>
void for_each_depth_range(Check check) {
    for (const DepthRange depth : all_depth_ranges) {
        INFO("depth=", frustum::to_string(depth));
        check(depth);
    }
}

} // namespace mtest
