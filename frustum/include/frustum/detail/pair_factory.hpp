// The one funnel through which every MatrixPair is made (STYLE.md habit 4):
// it stores matrix, inverse and depth range together and applies the sign
// convention (w > 0 inside). Internal: only constructors and operations of
// this library call it, each with an inverse it derived in closed form.
#pragma once

#include "frustum/matrix_pair.hpp"

namespace frustum::detail {

struct PairFactory {
    template <class T>
    static MatrixPair<T> make(const Mat4<T>& m, const Mat4<T>& inv, DepthRange depth, bool flips_winding) {
        // The clip point just inside the centre of the near face, taken back
        // to world space: its w must be positive, else negate both matrices.
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
};

} // namespace frustum::detail
