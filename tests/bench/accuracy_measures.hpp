// What the accuracy tables (ops_accuracy.cpp, lens_accuracy.cpp) and their check
// (tests/math/update_accuracy_test.cpp) measure with.
//
// column_error: the error of one inverse, max over its columns of
// |col - ref| / |ref| (Euclidean; the columns are points of very different
// sizes, so each is judged alone), up to the overall sign: a projective
// matrix is defined up to a factor, and the baseline does not apply the
// library's sign convention (w > 0 inside).
#pragma once

#include <frustum/types.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace bench {

inline double column_error(const frustum::Mat4<float>& value, const frustum::Mat4<double>& reference) {
    double worst[2] = {0.0, 0.0};
    for (int c = 0; c < 4; ++c) {
        const double scale = glm::length(reference[c]);
        worst[0] = std::max(worst[0], glm::length(glm::dvec4(value[c]) - reference[c]) / scale);
        worst[1] = std::max(worst[1], glm::length(glm::dvec4(value[c]) + reference[c]) / scale);
    }
    return std::min(worst[0], worst[1]);
}

// pair_residual: how well a float pair agrees with itself, the componentwise
// residual max_ij |(M inv - I)_ij| / (|M| |inv|)_ij, computed in double. A
// float matrix and its glm::inverse agree by construction (a few eps); an
// analytically updated inverse tracks the exact operation instead, so it
// agrees with its own rounded M a little less.
inline double pair_residual(const frustum::Mat4<float>& m, const frustum::Mat4<float>& inv) {
    const glm::dmat4 md(m), id(inv);
    double worst = 0.0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            double product = 0.0, scale = 0.0;
            for (int k = 0; k < 4; ++k) {
                product += md[k][r] * id[c][k];
                scale += std::abs(md[k][r] * id[c][k]);
            }
            worst = std::max(worst, std::abs(product - (c == r ? 1.0 : 0.0)) / scale);
        }
    }
    return worst;
}

// Errors of many cases: mean and quantiles (nearest rank, q (n - 1)).
struct Stats {
    std::vector<double> errors;
    void add(double e) { errors.push_back(e); }
    double mean() const {
        double s = 0.0;
        for (double e : errors) s += e;
        return errors.empty() ? 0.0 : s / static_cast<double>(errors.size());
    }
    double quantile(double q) {
        if (errors.empty()) return 0.0;
        std::sort(errors.begin(), errors.end());
        return errors[static_cast<std::size_t>(q * static_cast<double>(errors.size() - 1))];
    }
};

} // namespace bench
