// A matrix written as it is drawn: four rows, top to bottom, in reading
// order (GLM stores columns, so `Mat4<T>(a, b, c, ...)` lists the matrix
// transposed). The library's constructors lay their matrices out with it
// so the code reads like the ASCII matrices in projection.hpp:
//
//   const Mat4<T> m = from_rows<T>({sx,   0,  cx, 0},
//                                  { 0,  sy,  cy, 0},
//                                  { 0,   0,   a, b},
//                                  { 0,   0,  -1, 0});
//
// Every entry is copied as given: the result is bit for bit the matrix
// built entry by entry.
#pragma once

#include "frustum/types.hpp"

namespace frustum {

template <class T>
Mat4<T> from_rows(const Vec4<T>& r0, const Vec4<T>& r1, const Vec4<T>& r2, const Vec4<T>& r3) {
    return Mat4<T>(Vec4<T>(r0.x, r1.x, r2.x, r3.x), Vec4<T>(r0.y, r1.y, r2.y, r3.y),
                   Vec4<T>(r0.z, r1.z, r2.z, r3.z), Vec4<T>(r0.w, r1.w, r2.w, r3.w));
}

} // namespace frustum
