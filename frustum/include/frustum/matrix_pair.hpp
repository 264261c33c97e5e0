// MatrixPair<T>: a projection (or view-projection) matrix M and its inverse,
// always together (paper §1). Planes come from the rows of M (§3.1), key
// points from the columns of the inverse (§3.2); operations (§5) update both
// analytically, so nothing here ever inverts a matrix.
//
// Column-vector convention (GLM): clip = M * world. The paper's column m_i
// is row i of M here, and its inverse row m_i' is column i of inverse().
//
// Sign: a projective matrix is defined up to a factor. Every pair is scaled
// so that w > 0 for points inside the frustum (just inside the centre of the
// near face), which makes all planes inward-positive.
#pragma once

#include "frustum/depth_range.hpp"
#include "frustum/types.hpp"

namespace frustum {

namespace detail {
struct PairFactory;
// Passkey: only PairFactory can make one, so only the library's operations
// can use the column constructor below (a Result builds its pair in place
// with it: no temporary, no 16-byte-at-a-time copy).
class PairKey {
    PairKey() {} // user-provided: no aggregate initialization from outside
    friend struct PairFactory;
};
} // namespace detail

template <class T>
class MatrixPair {
public:
    using Scalar = T;

    const Mat4<T>& matrix() const { return matrix_; }
    const Mat4<T>& inverse() const { return inverse_; }
    DepthRange depth() const { return static_cast<DepthRange>(traits_ & depth_mask); }
    // True after an odd number of reflections: draw with the front face
    // swapped (docs/errata.md erratum 3).
    bool flips_winding() const { return (traits_ & flips_bit) != 0; }

    // The same frustum for another depth range: only row 2 of M changes,
    // z' = a z + b w, and the inverse follows in closed form.
    MatrixPair with_depth_range(DepthRange target) const;

    // The same pair in another scalar type (e.g. double reference -> float).
    template <class U>
    MatrixPair<U> cast() const;

    // Internal (see detail::PairKey): a pair from its eight columns, each
    // written with one whole-column store.
    MatrixPair(detail::PairKey, const Vec4<T>& m0, const Vec4<T>& m1, const Vec4<T>& m2, const Vec4<T>& m3,
               const Vec4<T>& i0, const Vec4<T>& i1, const Vec4<T>& i2, const Vec4<T>& i3, unsigned traits)
        : matrix_(m0, m1, m2, m3), inverse_(i0, i1, i2, i3), traits_(traits) {}

private:
    friend struct detail::PairFactory;
    template <class U>
    friend class MatrixPair;
    MatrixPair(const Mat4<T>& m, const Mat4<T>& inv, DepthRange depth, bool flips)
        : matrix_(m), inverse_(inv), traits_(static_cast<unsigned>(depth) | (flips ? flips_bit : 0u)) {}

    static constexpr unsigned depth_mask = 0xffu;
    static constexpr unsigned flips_bit = 0x100u;
    unsigned traits() const { return traits_; }

    Mat4<T> matrix_{1};
    Mat4<T> inverse_{1};
    // Depth range and winding packed in one word: written with one store, so
    // copying a fresh pair does not stall on store forwarding (measured:
    // ~20% of clip_oblique's time with two separate fields).
    unsigned traits_ = 0;
};

// A rigid transform (rotation + translation) and its inverse: a view matrix.
template <class T>
struct RigidTransform {
    Mat4<T> matrix{1};
    Mat4<T> inverse{1};

    // R must be a rotation; the inverse is [R^T | -R^T t].
    static RigidTransform from_rotation_translation(const Mat3<T>& rotation, const Vec3<T>& translation);
};

template <class T>
template <class U>
MatrixPair<U> MatrixPair<T>::cast() const {
    return MatrixPair<U>(Mat4<U>(matrix_), Mat4<U>(inverse_), depth(), flips_winding());
}

} // namespace frustum
