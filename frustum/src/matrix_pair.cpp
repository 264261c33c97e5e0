#include "frustum/matrix_pair.hpp"

#include "frustum/detail/pair_factory.hpp"

namespace frustum {

template <class T>
MatrixPair<T> MatrixPair<T>::with_depth_range(DepthRange target) const {
    // z' = a z + b w maps (z_n, z_f) of this range onto the target's.
    const T a = clip_z_span<T>(target) / clip_z_span<T>(depth());
    const T b = clip_z_near<T>(target) - a * clip_z_near<T>(depth());
    Mat4<T> m = matrix_;
    for (int j = 0; j < 4; ++j) {
        m[j].z = a * matrix_[j].z + b * matrix_[j].w; // row 2 <- a row 2 + b row 3
    }
    // Inverse: z = (z' - b w) / a, so column 2 scales by 1/a and column 3
    // picks up -(b/a) column 2.
    Mat4<T> inv = inverse_;
    inv[2] = inverse_[2] / a;
    inv[3] = inverse_[3] - (b / a) * inverse_[2];
    return detail::PairFactory::keep_sign(m, inv, target, flips_winding());
}

template class MatrixPair<float>;
template class MatrixPair<double>;

} // namespace frustum
