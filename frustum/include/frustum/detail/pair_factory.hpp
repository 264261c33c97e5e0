// The one funnel through which every MatrixPair is made:
// it stores matrix, inverse and depth range together and applies the sign
// convention (w > 0 inside): decided once by make() when a frustum is born,
// kept by keep_sign() through every operation after that. Internal: only constructors and operations of
// this library call it, each with an inverse it derived in closed form.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

#include <utility>

namespace frustum::detail {

struct PairFactory {
    // For constructors and imported matrices: the clip point just inside the
    // centre of the near face, taken back to world space, must have w > 0;
    // else both matrices are negated.
    template <class T>
    static MatrixPair<T> make(const Mat4<T>& m, const Mat4<T>& inv, DepthRange depth, bool flips_winding) {
        const T z_near = clip_z_near<T>(depth);
        const T z_inside = z_near + T(0.01) * clip_z_span<T>(depth);
        const T w_world = inv[2][3] * z_inside + inv[3][3];
        MatrixPair<T> pair(m, inv, depth, flips_winding);
        if (w_world < T(0)) {
            pair.matrix_ = -pair.matrix_;
            pair.inverse_ = -pair.inverse_;
        }
        return pair;
    }

    // For operations that keep row 3 of M (the clip w) up to a positive
    // factor: crop, reflect, clip_oblique, depth-range changes, a rigid view,
    // and pairs built from inward planes. Their sign is already right, and
    // re-deciding it from the near-face centre would be wrong after an
    // oblique clip whose plane crosses the view axis behind the eye (that
    // centre is then behind the eye, where w < 0 is correct).
    template <class T>
    static MatrixPair<T> keep_sign(const Mat4<T>& m, const Mat4<T>& inv, DepthRange depth, bool flips_winding) {
        return MatrixPair<T>(m, inv, depth, flips_winding);
    }

    // keep_sign() for the hot operations (crop, reflect, clip, mirror): the
    // pair is built from its columns directly inside the returned Result.
    template <class T>
    static Result<MatrixPair<T>> keep_sign_result(const Vec4<T>& m0, const Vec4<T>& m1, const Vec4<T>& m2,
                                                  const Vec4<T>& m3, const Vec4<T>& i0, const Vec4<T>& i1,
                                                  const Vec4<T>& i2, const Vec4<T>& i3, unsigned traits) {
        return Result<MatrixPair<T>>(std::in_place, PairKey{}, m0, m1, m2, m3, i0, i1, i2, i3, traits);
    }
    template <class T>
    static MatrixPair<T> keep_sign_columns(const Vec4<T>& m0, const Vec4<T>& m1, const Vec4<T>& m2,
                                           const Vec4<T>& m3, const Vec4<T>& i0, const Vec4<T>& i1,
                                           const Vec4<T>& i2, const Vec4<T>& i3, unsigned traits) {
        return MatrixPair<T>(PairKey{}, m0, m1, m2, m3, i0, i1, i2, i3, traits);
    }
    // Depth range and winding of a pair, as one word.
    template <class T>
    static unsigned traits(const MatrixPair<T>& pair) {
        return pair.traits();
    }
    // The same with the winding flipped (a reflection).
    template <class T>
    static unsigned flipped_traits(const MatrixPair<T>& pair) {
        return pair.traits() ^ MatrixPair<T>::flips_bit;
    }
};

} // namespace frustum::detail
