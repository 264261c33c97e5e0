// DepthRange: where the near and far planes land in clip-space z/w. It is
// part of every MatrixPair, so a recipe written for one range can never be
// silently applied to another (docs/conventions.md).
#pragma once

#include <string_view>

namespace frustum {

enum class DepthRange {
    ZeroToOne,         // near -> 0, far -> 1: the paper's, Vulkan, D3D, GL with clip control
    MinusOneToOne,     // near -> -1, far -> 1: classic OpenGL / OpenGL ES
    ReversedZeroToOne, // near -> 1, far -> 0: reversed-Z for float depth buffers
};

// Clip-space z/w of the near plane.
template <class T>
constexpr T clip_z_near(DepthRange depth) {
    switch (depth) {
    case DepthRange::ZeroToOne: return T(0);
    case DepthRange::MinusOneToOne: return T(-1);
    case DepthRange::ReversedZeroToOne: return T(1);
    }
    return T(0);
}

// Clip-space z/w of the far plane.
template <class T>
constexpr T clip_z_far(DepthRange depth) {
    switch (depth) {
    case DepthRange::ZeroToOne: return T(1);
    case DepthRange::MinusOneToOne: return T(1);
    case DepthRange::ReversedZeroToOne: return T(0);
    }
    return T(1);
}

// z_far - z_near: 1, 2 or -1. Its sign says which way depth grows.
template <class T>
constexpr T clip_z_span(DepthRange depth) {
    return clip_z_far<T>(depth) - clip_z_near<T>(depth);
}

// The centre of the depth range, (z_near + z_far) / 2 (paper: 0.5).
template <class T>
constexpr T clip_z_mid(DepthRange depth) {
    return (clip_z_near<T>(depth) + clip_z_far<T>(depth)) / T(2);
}

constexpr std::string_view to_string(DepthRange depth) {
    switch (depth) {
    case DepthRange::ZeroToOne: return "zero_to_one";
    case DepthRange::MinusOneToOne: return "minus_one_to_one";
    case DepthRange::ReversedZeroToOne: return "reversed_zero_to_one";
    }
    return "?";
}

} // namespace frustum
