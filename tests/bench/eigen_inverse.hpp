// Eigen's 4x4 inverse (SIMD, cofactor form) as a second baseline for the
// speed benchmark only (issue 14); the library itself never uses Eigen.
#pragma once

#include <frustum/types.hpp>

#include <Eigen/Dense>

namespace bench {

struct EigenInverse {
    // GLM and Eigen both store column-major: map in place, no copies.
    template <class T>
    frustum::Mat4<T> operator()(const frustum::Mat4<T>& m) const {
        frustum::Mat4<T> out;
        Eigen::Map<Eigen::Matrix<T, 4, 4>> destination(&out[0][0]);
        destination = Eigen::Map<const Eigen::Matrix<T, 4, 4>>(&m[0][0]).inverse();
        return out;
    }
};

} // namespace bench
