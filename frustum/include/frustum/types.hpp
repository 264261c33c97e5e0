// Short names for the GLM types the library uses, templated on the scalar
// (float is the mobile default; double is for references and ports).
#pragma once

#include <glm/glm.hpp>

namespace frustum {

template <class T> using Vec2 = glm::vec<2, T, glm::defaultp>;
template <class T> using Vec3 = glm::vec<3, T, glm::defaultp>;
template <class T> using Vec4 = glm::vec<4, T, glm::defaultp>;
template <class T> using Mat3 = glm::mat<3, 3, T, glm::defaultp>;
template <class T> using Mat4 = glm::mat<4, 4, T, glm::defaultp>;

// Row i of a column-major GLM matrix: the paper's column m_i (docs/conventions.md).
template <class T>
Vec4<T> row(const Mat4<T>& m, int i) {
    return Vec4<T>(m[0][i], m[1][i], m[2][i], m[3][i]);
}

template <class T>
void set_row(Mat4<T>& m, int i, const Vec4<T>& r) {
    m[0][i] = r.x;
    m[1][i] = r.y;
    m[2][i] = r.z;
    m[3][i] = r.w;
}

} // namespace frustum
