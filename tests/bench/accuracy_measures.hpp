// What the accuracy tables (ops_accuracy.cpp) and their check
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
