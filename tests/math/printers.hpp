// Printers of the math suite, so that a failing CHECK shows numbers:
// vectors, matrices (by rows), pairs, planes and close() comparisons.
#pragma once

#include "support_basics.hpp"

namespace mtest {


template <class T>
std::string num(T v) {
    std::ostringstream s;
    s << std::setprecision(std::numeric_limits<T>::max_digits10) << v;
    return s.str();
}

template <int N, class T>
std::string vec_text(const glm::vec<N, T, glm::defaultp>& v) {
    std::string s = "(";
    for (int i = 0; i < N; ++i) {
        s += (i ? ", " : "") + num(v[i]);
    }
    return s + ")";
}

// Printed by ROWS, as the maths is written (GLM stores columns).
template <class T>
std::string mat_text(const Mat4<T>& m) {
    std::string s = "rows[";
    for (int r = 0; r < 4; ++r) {
        s += (r ? ", " : "") + vec_text(frustum::row(m, r));
    }
    return s + "]";
}

template <class T>
std::string pair_text(const MatrixPair<T>& p) {
    return std::string("MatrixPair{depth=") + std::string(frustum::to_string(p.depth())) +
           " flips_winding=" + (p.flips_winding() ? "true" : "false") + " matrix=" + mat_text(p.matrix()) +
           " inverse=" + mat_text(p.inverse()) + "}";
}

// A value compared within an absolute tolerance (see close()).
template <class V>
struct Close {
    V expected;
    double tolerance;
};

} // namespace mtest

namespace doctest {

template <class T>
struct StringMaker<glm::vec<3, T, glm::defaultp>> {
    static String convert(const glm::vec<3, T, glm::defaultp>& v) { return mtest::vec_text(v).c_str(); }
};
template <class T>
struct StringMaker<glm::vec<4, T, glm::defaultp>> {
    static String convert(const glm::vec<4, T, glm::defaultp>& v) { return mtest::vec_text(v).c_str(); }
};
template <class T>
struct StringMaker<glm::mat<4, 4, T, glm::defaultp>> {
    static String convert(const glm::mat<4, 4, T, glm::defaultp>& m) { return mtest::mat_text(m).c_str(); }
};
template <class T>
struct StringMaker<frustum::Plane<T>> {
    static String convert(const frustum::Plane<T>& p) { return ("Plane" + mtest::vec_text(p.abcd)).c_str(); }
};
template <class T>
struct StringMaker<frustum::MatrixPair<T>> {
    static String convert(const frustum::MatrixPair<T>& p) { return mtest::pair_text(p).c_str(); }
};
template <class V>
struct StringMaker<mtest::Close<V>> {
    static String convert(const mtest::Close<V>& c) {
        return (StringMaker<V>::convert(c.expected) + " +- " + mtest::num(c.tolerance).c_str());
    }
};

} // namespace doctest
