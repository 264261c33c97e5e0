// clip_oblique() with the plane already carried into clip space, so that
// mirror() can pass the exact c' of the reflected pair (-(M^-T c), since
// R^T c = -c) instead of recomputing it from the updated inverse, which
// loses digits to cancellation. For the same reason k = (m3 . Q) / (c . Q)
// may be formed on the unreflected pair: with Q0 = M^-1 q,
// m3 R . R Q0 = m3 . Q0 and c . R Q0 = -(c . Q0), so k_sign = -1.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

namespace frustum::detail {

// c: the unit plane in world space; c_clip: the same plane in the pair's
// clip space (c_clip = M^-T c); k = k_sign (m3 . Q) / (c . Q) with m3 and
// Q = M^-1 q taken from k_source (the pair itself for a plain clip).
template <class T>
Result<MatrixPair<T>> clip_oblique_in_clip_space(const MatrixPair<T>& pair, const Vec4<T>& c, const Vec4<T>& c_clip,
                                                 const MatrixPair<T>& k_source, T k_sign, const char* function);

} // namespace frustum::detail
