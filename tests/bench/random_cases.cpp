#include "random_cases.hpp"

#include <random>

namespace bench {

std::vector<MirrorCase> make_mirror_cases(int count, frustum::DepthRange depth, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const auto positive = [&](double lo, double hi) { return lo + (hi - lo) * 0.5 * (u(rng) + 1.0); };
    std::vector<MirrorCase> cases;
    cases.reserve(static_cast<std::size_t>(count));
    while (static_cast<int>(cases.size()) < count) {
        const double near_m = positive(0.05, 1.0);
        const double far_m = near_m * positive(10.0, 2000.0);
        const double left = u(rng) * near_m, right = left + near_m * positive(0.2, 4.0);
        const double bottom = u(rng) * near_m, top = bottom + near_m * positive(0.2, 4.0);
        // One draw per statement (argument order is unspecified), z first:
        // the order these cases were always drawn in (docs' tables use them).
        const double eye_z = 5.0 * u(rng), eye_y = positive(1.0, 7.0), eye_x = 5.0 * u(rng);
        const glm::dvec3 eye(eye_x, eye_y, eye_z);
        const double target_z = 3.0 * u(rng), target_y = u(rng), target_x = 3.0 * u(rng);
        const glm::dvec3 target(target_x, target_y, target_z);
        auto projection = frustum::off_axis(left, right, bottom, top, near_m, std::optional<double>(far_m), depth);
        auto view = frustum::look_at(eye, target, glm::dvec3(0, 1, 0));
        if (!projection || !view) {
            continue;
        }
        const auto camera = frustum::compose(*projection, *view);
        // A roughly horizontal mirror below the eye, tilted up to ~27 degrees.
        const double tilt_z = 0.5 * u(rng), tilt_x = 0.5 * u(rng);
        const glm::dvec3 normal = glm::normalize(glm::dvec3(tilt_x, 1.0, tilt_z));
        const double on_z = u(rng), on_y = 0.5 * u(rng), on_x = u(rng);
        const glm::dvec3 on_plane(on_x, on_y, on_z);
        const frustum::Plane<double> plane(glm::dvec4(normal, -glm::dot(normal, on_plane)));
        if (!frustum::mirror(camera, plane)) {
            continue; // eye behind the mirror or nothing visible in it
        }
        const glm::dvec3 a1 = glm::normalize(glm::cross(normal, glm::dvec3(0, 0, 1))) * positive(0.5, 3.0);
        const glm::dvec3 a2 = glm::normalize(glm::cross(normal, a1)) * positive(0.5, 3.0);
        const frustum::Rectangle<double> rectangle{on_plane - 0.5 * (a1 + a2), a2, a1};
        cases.push_back(MirrorCase{camera, plane, rectangle, eye});
    }
    return cases;
}

} // namespace bench
