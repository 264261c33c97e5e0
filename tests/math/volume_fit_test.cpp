// Paper §4.3: volume approximation by the optimal frustum origin.
#include "support.hpp"

#include <random>

using namespace frustum;

namespace {

// Three draws, one per statement (argument order is unspecified), z first:
// the order these cases were always drawn in.
glm::dvec3 draw_zyx(std::uniform_real_distribution<double>& u, std::mt19937& rng) {
    const double z = u(rng);
    const double y = u(rng);
    const double x = u(rng);
    return {x, y, z};
}

// The target of an exact frustum: its own side planes and near corners.
VolumeTarget<double> target_of(const MatrixPair<double>& camera) {
    const auto p = planes(camera);
    const auto k = key_points(camera);
    glm::dvec3 c[4];
    for (int i = 0; i < 4; ++i) c[i] = glm::dvec3(to_point(k.corners[i], 1e-12));
    VolumeTarget<double> t;
    // C2 top-left, C1 top-right, C4 bottom-right, C3 bottom-left (eq. 8 order)
    t.near_points = {c[1], c[0], c[3], c[2]};
    t.side_normals = {p.top.normal(), p.right.normal(), p.bottom.normal(), p.left.normal()};
    t.near = p.near;
    return t;
}

MatrixPair<double> camera_at(const glm::dvec3& eye) {
    const auto projection = off_axis(-0.3, 0.5, -0.2, 0.35, 0.5, std::optional<double>(40.0), DepthRange::ZeroToOne);
    const auto view = look_at(eye, glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
    return compose(*projection, *view);
}

} // namespace

TEST_SUITE("math") {

TEST_CASE("the volume gradient matches central finite differences (erratum 6)") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const auto target = target_of(camera_at(glm::dvec3(1, 2, 5)));
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec3 origin = glm::dvec3(1, 2, 5) + draw_zyx(u, rng);
        glm::dvec3 gradient;
        volume_objective(target, origin, &gradient);
        glm::dvec3 numeric;
        const double h = 1e-6;
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 e(0.0);
            e[a] = h;
            numeric[a] = (volume_objective(target, origin + e) - volume_objective(target, origin - e)) / (2 * h);
        }
        // Central differences are O(h^2) ~ 1e-12 plus rounding ~ eps/h ~ 1e-10.
        CHECK(glm::length(gradient - numeric) < 1e-7 * (1.0 + glm::length(numeric)));
    }
}

TEST_CASE("an exact frustum is its own optimum: F = 4 at its eye, gradient zero") {
    const glm::dvec3 eye(1, 2, 5);
    const auto target = target_of(camera_at(eye));
    glm::dvec3 gradient;
    CHECK(volume_objective(target, eye, &gradient) == doctest::Approx(4.0).epsilon(1e-12));
    CHECK(glm::length(gradient) < 1e-9);
}

TEST_CASE("fit_volume recovers the origin of slightly perturbed targets and builds a valid frustum") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const glm::dvec3 jitter = draw_zyx(u, rng);
        const glm::dvec3 eye(2 * jitter.x, 1.5 + jitter.y, 5 + jitter.z);
        auto target = target_of(camera_at(eye));
        for (auto& t : target.side_normals) {
            t = glm::normalize(t + 0.01 * draw_zyx(u, rng));
        }
        const auto fit = fit_volume(target, 30.0, DepthRange::ZeroToOne);
        REQUIRE(fit.ok());
        CHECK(fit->objective > 3.99);     // cosines of ~0.6 degree errors
        CHECK(fit->objective <= 4.0 + 1e-12);
        CHECK(glm::length(fit->origin - eye) < 0.05 * glm::length(eye));
        CHECK(fit->iterations < 200);
        CHECK(validate(fit->pair).valid());
        CHECK(mtest::inverse_residual(fit->pair) < 1e-11);
        // It improved on the paper's start point, intersect(T0, T1, T2).
        glm::dvec3 start_gradient;
        const auto start_value = volume_objective(target, eye, &start_gradient);
        CHECK(fit->objective >= start_value - 1e-9);
    }
}

TEST_CASE("fit_volume rejects a bad far distance") {
    const auto target = target_of(camera_at(glm::dvec3(1, 2, 5)));
    const auto fit = fit_volume(target, -1.0, DepthRange::ZeroToOne);
    CHECK_FALSE(fit.ok());
    CHECK(fit.error() == "frustum::fit_volume(): far distance must be > 0 and finite, got far=-1");
}

} // TEST_SUITE
