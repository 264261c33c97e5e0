// The baseline the paper improves on: update only the projection matrix
// with the same forward formula as the library, then re-invert it with
// glm::inverse. Used by the benchmarks, never by the library.
#pragma once

#include <frustum/frustum.hpp>
#include <glm/gtc/matrix_inverse.hpp>

namespace bench {

// The inversion of the baseline: glm::inverse (the default), or another
// library's (eigen_inverse.hpp) in the speed benchmark.
struct GlmInverse {
    template <class T>
    frustum::Mat4<T> operator()(const frustum::Mat4<T>& m) const {
        return glm::inverse(m);
    }
};

template <class T>
struct RawPair {
    frustum::Mat4<T> matrix, inverse;
};

template <class T>
RawPair<T> raw(const frustum::MatrixPair<T>& pair) {
    return {pair.matrix(), pair.inverse()};
}

// eq. 14: rows 0 and 1 pick up row 3.
template <class T, class Inverse = GlmInverse>
RawPair<T> crop_reinvert(const RawPair<T>& p, const frustum::CropRect<T>& r, Inverse inverse = {}) {
    const T w = r.full_width / r.width, h = r.full_height / r.height;
    frustum::Mat4<T> m = p.matrix;
    const frustum::Vec4<T> m3 = frustum::row(m, 3);
    frustum::set_row(m, 0, w * frustum::row(m, 0) + (w - T(1) - T(2) * r.x / r.width) * m3);
    frustum::set_row(m, 1, h * frustum::row(m, 1) + (h - T(1) - T(2) * r.y / r.height) * m3);
    return {m, inverse(m)};
}

// eq. 16: M R for a unit plane.
template <class T, class Inverse = GlmInverse>
RawPair<T> reflect_reinvert(const RawPair<T>& p, const frustum::Plane<T>& unit_plane, Inverse inverse = {}) {
    const frustum::Mat4<T> m = p.matrix * frustum::reflection_matrix(unit_plane);
    return {m, inverse(m)};
}

// §5.2 with the clip-space corner (erratum 2): the new matrix only, given
// the plane already carried into clip space.
template <class T>
frustum::Mat4<T> clip_matrix(const frustum::Mat4<T>& matrix, const frustum::Vec4<T>& c,
                             const frustum::Vec4<T>& c_clip, frustum::DepthRange depth) {
    const T z_near = frustum::clip_z_near<T>(depth), span = frustum::clip_z_span<T>(depth);
    const frustum::Vec4<T> q(c_clip.x >= T(0) ? T(1) : T(-1), c_clip.y >= T(0) ? T(1) : T(-1),
                             frustum::clip_z_far<T>(depth), T(1));
    const T k = T(1) / glm::dot(c_clip, q);
    frustum::Mat4<T> m = matrix;
    frustum::set_row(m, 2, (span * k) * c + z_near * frustum::row(matrix, 3));
    return m;
}

// Reads the current inverse to carry the plane into clip space, as any
// implementation must.
template <class T, class Inverse = GlmInverse>
RawPair<T> clip_reinvert(const RawPair<T>& p, const frustum::Plane<T>& unit_plane, frustum::DepthRange depth,
                         Inverse inverse = {}) {
    const frustum::Vec4<T> c_clip = glm::transpose(p.inverse) * unit_plane.abcd;
    const frustum::Mat4<T> m = clip_matrix(p.matrix, unit_plane.abcd, c_clip, depth);
    return {m, inverse(m)};
}

// Reflect then clip, inverting once at the end. The plane in the reflected
// clip space needs no new inverse: (R M^-1)^T c = -(M^-T c) since R^T c = -c.
template <class T, class Inverse = GlmInverse>
RawPair<T> mirror_reinvert(const RawPair<T>& p, const frustum::Plane<T>& unit_plane, frustum::DepthRange depth,
                           Inverse inverse = {}) {
    const frustum::Mat4<T> reflected = p.matrix * frustum::reflection_matrix(unit_plane);
    const frustum::Vec4<T> c_clip = -(glm::transpose(p.inverse) * unit_plane.abcd);
    const frustum::Mat4<T> m = clip_matrix(reflected, unit_plane.abcd, c_clip, depth);
    return {m, inverse(m)};
}

} // namespace bench
