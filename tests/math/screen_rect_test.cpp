// screen_rect (screen_rect.hpp): the pixel rectangle of a convex polygon's
// visible part, clipped in homogeneous clip space (near plane included).
#include "support.hpp"

using namespace mtest;
using frustum::CropRect;

namespace {

// 90 degrees, square, near 1, far 10, at the origin looking down -z: a
// point (x, y, z) lands at NDC (x / -z, y / -z).
template <class T>
MatrixPair<T> square_camera(DepthRange depth, bool infinite = false) {
    const auto p = frustum::perspective<T>(T(pi / 2), T(1), T(1),
                                           infinite ? std::optional<T>() : std::optional<T>(T(10)), depth);
    REQUIRE(p.ok());
    return *p;
}

template <class T>
std::vector<Vec3<T>> quad(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
    return {a, b, c, d};
}

template <class T>
void check_rect(const CropRect<T>& r, double x, double y, double w, double h, double tolerance) {
    CHECK(std::abs(double(r.x) - x) <= tolerance);
    CHECK(std::abs(double(r.y) - y) <= tolerance);
    CHECK(std::abs(double(r.width) - w) <= tolerance);
    CHECK(std::abs(double(r.height) - h) <= tolerance);
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("screen_rect: a quad at z = -2 spanning [-1, 1]^2 covers the middle half of a 100 x 100 image", T,
                   float, double) {
    for (const DepthRange depth : all_depth_ranges) {
        const auto r = frustum::screen_rect(
            square_camera<T>(depth), quad<T>({-1, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-1, 1, -2}), T(100), T(100));
        REQUIRE_MESSAGE(r.ok(), r.error());
        REQUIRE(r->has_value());
        check_rect(**r, 25, 25, 50, 50, 1e-4);
        CHECK((*r)->full_width == T(100));
        CHECK((*r)->full_height == T(100));
    }
}

TEST_CASE_TEMPLATE("screen_rect: a floor quad crossing the eye plane is clipped by the near plane before dividing", T,
                   float, double) {
    // Floor y = -1, x in [-1, 1], z from -3 (in front) to +3 (behind the
    // eye). Visible: z in [-3, -1] (near = 1): y_ndc from -1 (at z = -1) to
    // -1/3 (at z = -3), x_ndc reaching +-1 at z = -1. So x 0..100 and
    // y 0..33.33. Dividing the corners behind the eye would have given
    // y_ndc = +1/3 for z = +3 (y up to 66.67): the bug this function avoids.
    const auto floor = quad<T>({-1, -1, -3}, {1, -1, -3}, {1, -1, 3}, {-1, -1, 3});
    for (const DepthRange depth : all_depth_ranges) {
        const auto r = frustum::screen_rect(square_camera<T>(depth), floor, T(100), T(100));
        REQUIRE_MESSAGE(r.ok(), r.error());
        REQUIRE(r->has_value());
        check_rect(**r, 0, 0, 100, 100.0 / 3, 1e-3);
        const Vec4<T> behind = square_camera<T>(depth).matrix() * Vec4<T>(-1, -1, 3, 1);
        CHECK(behind.w < T(0)); // the naive division would flip this corner to the top half
        CHECK((behind.y / behind.w + 1) * 50 > T(60));
    }
}

TEST_CASE_TEMPLATE("screen_rect: nothing visible gives an empty result (behind, aside, beyond far, edge-on)", T, float,
                   double) {
    const MatrixPair<T> cam = square_camera<T>(DepthRange::ZeroToOne);
    const auto empty = [&](const std::vector<Vec3<T>>& polygon, const MatrixPair<T>& pair) {
        const auto r = frustum::screen_rect(pair, polygon, T(64), T(48));
        REQUIRE_MESSAGE(r.ok(), r.error());
        return !r->has_value();
    };
    CHECK(empty(quad<T>({-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}), cam));        // behind the eye
    CHECK(empty(quad<T>({5, -1, -2}, {6, -1, -2}, {6, 1, -2}, {5, 1, -2}), cam));      // right of the frustum
    CHECK(empty(quad<T>({-1, -1, -20}, {1, -1, -20}, {1, 1, -20}, {-1, 1, -20}), cam)); // beyond far
    CHECK(empty(quad<T>({-1, 0, -2}, {1, 0, -2}, {1, 0, -4}, {-1, 0, -4}), cam));      // edge-on (y = 0 plane)
    // Between the eye and the near plane: clipped away by the near plane.
    CHECK(empty(quad<T>({-0.1f, -0.1f, -0.5f}, {0.1f, -0.1f, -0.5f}, {0.1f, 0.1f, -0.5f}, {-0.1f, 0.1f, -0.5f}), cam));
    // With an infinite far plane the far quad is visible.
    CHECK_FALSE(empty(quad<T>({-1, -1, -20}, {1, -1, -20}, {1, 1, -20}, {-1, 1, -20}),
                      square_camera<T>(DepthRange::ZeroToOne, true)));
}

TEST_CASE_TEMPLATE("screen_rect: random quads, every visible sample inside, bounds equal a world-space clip", T, float,
                   double) {
    int non_empty = 0;
    for_each_random_camera<T>(7201, 200, [&](Random& rng, const CameraSpec& spec, const MatrixPair<T>& pair) {
        INFO("camera: ", spec.text());
        // A quad around a point inside the frustum, up to 3x its distance wide.
        const glm::dvec4 h = glm::dmat4(pair.inverse()) * random_clip_point(rng, spec.depth, 0.1);
        const glm::dvec3 centre = glm::dvec3(h) / h.w;
        const glm::dvec3 a = rng.unit_vector() * rng.uniform(0.5, 30);
        glm::dvec3 b = glm::cross(a, rng.unit_vector());
        b = glm::normalize(b) * rng.uniform(0.5, 30);
        const std::vector<Vec3<T>> polygon = {Vec3<T>(centre - a - b), Vec3<T>(centre + a - b),
                                              Vec3<T>(centre + a + b), Vec3<T>(centre - a + b)};
        const auto r = frustum::screen_rect(pair, polygon, T(320), T(200));
        REQUIRE_MESSAGE(r.ok(), r.error());
        // Dense samples of the quad, projected where they are visible.
        double x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
        const int n = 96;
        for (int u = 0; u <= n; ++u) {
            for (int v = 0; v <= n; ++v) {
                const glm::dvec3 p = centre + a * (2.0 * u / n - 1) + b * (2.0 * v / n - 1);
                const glm::dvec4 c = glm::dmat4(pair.matrix()) * glm::dvec4(p, 1);
                if (!clip_inside(c, spec.depth)) continue;
                const double px = (c.x / c.w + 1) * 160, py = (c.y / c.w + 1) * 100;
                x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
            }
        }
        if (!r->has_value()) {
            CHECK(x0 > x1); // no sample visible either
            return;
        }
        ++non_empty;
        const CropRect<T>& rect = **r;
        const double slack = sizeof(T) == 4 ? 0.05 : 1e-6; // pixels
        CHECK(x0 >= double(rect.x) - slack);
        CHECK(y0 >= double(rect.y) - slack);
        CHECK(x1 <= double(rect.x + rect.width) + slack);
        CHECK(y1 <= double(rect.y + rect.height) + slack);
        // Tight: an independent reference clips the quad in WORLD space
        // against the normalized planes (every vertex left is then in front
        // of the eye and safe to divide) and bounds the projected vertices.
        std::vector<glm::dvec3> world;
        for (const auto& p : polygon) world.push_back(glm::dvec3(p));
        for (const auto& plane : frustum::planes(MatrixPair<double>(make<double>(spec))).as_array()) {
            if (!plane || world.empty()) continue;
            std::vector<glm::dvec3> next;
            for (std::size_t k = 0; k < world.size(); ++k) {
                const glm::dvec3 p = world[k], q = world[(k + 1) % world.size()];
                const double dp = plane->distance(p), dq = plane->distance(q);
                if (dp >= 0) next.push_back(p);
                if ((dp >= 0) != (dq >= 0)) next.push_back(p + (q - p) * (dp / (dp - dq)));
            }
            world.swap(next);
        }
        REQUIRE_FALSE(world.empty());
        double rx0 = 1e30, rx1 = -1e30, ry0 = 1e30, ry1 = -1e30;
        for (const glm::dvec3& p : world) {
            const glm::dvec4 c = glm::dmat4(make<double>(spec).matrix()) * glm::dvec4(p, 1);
            const double px = std::clamp((c.x / c.w + 1) * 160, 0.0, 320.0);
            const double py = std::clamp((c.y / c.w + 1) * 100, 0.0, 200.0);
            rx0 = std::min(rx0, px), rx1 = std::max(rx1, px), ry0 = std::min(ry0, py), ry1 = std::max(ry1, py);
        }
        const double tolerance = sizeof(T) == 4 ? 0.05 : 1e-6; // pixels
        CHECK(std::abs(double(rect.x) - rx0) <= tolerance);
        CHECK(std::abs(double(rect.x + rect.width) - rx1) <= tolerance);
        CHECK(std::abs(double(rect.y) - ry0) <= tolerance);
        CHECK(std::abs(double(rect.y + rect.height) - ry1) <= tolerance);
        // Always a valid crop of the image.
        CHECK(frustum::crop(pair, rect).ok());
    });
    CHECK(non_empty >= 150);
}

TEST_CASE_TEMPLATE("screen_rect: intersect() of a recursion level with its parent", T, float, double) {
    const CropRect<T> parent{10, 20, 50, 40, 100, 80};
    const auto both = frustum::intersect(parent, CropRect<T>{40, 0, 60, 30, 100, 80});
    REQUIRE(both.has_value());
    CHECK(both->x == T(40));
    CHECK(both->y == T(20));
    CHECK(both->width == T(20));
    CHECK(both->height == T(10));
    CHECK_FALSE(frustum::intersect(parent, CropRect<T>{60, 20, 10, 10, 100, 80}).has_value()); // touching edge
    CHECK_FALSE(frustum::intersect(parent, CropRect<T>{10, 20, 50, 40, 100, 81}).has_value()); // other image
}

TEST_CASE_TEMPLATE("screen_rect: errors, exact texts", T, float, double) {
    const MatrixPair<T> cam = square_camera<T>(DepthRange::ZeroToOne);
    const auto square = quad<T>({-1, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-1, 1, -2});
    CHECK(frustum::screen_rect(cam, square, T(0), T(100)).error() ==
          "frustum::screen_rect(): image sizes must be finite and > 0, got width_px=0 height_px=100");
    CHECK(frustum::screen_rect(cam, std::vector<Vec3<T>>{{0, 0, -1}, {1, 0, -1}}, T(10), T(10)).error() ==
          "frustum::screen_rect(): polygon needs at least 3 points, got points=2");
    CHECK(frustum::screen_rect(cam, quad<T>({0, 0, -1}, {1, 0, -1}, {1, std::numeric_limits<T>::infinity(), -1},
                                            {0, 1, -1}),
                               T(10), T(10))
              .error() == "frustum::screen_rect(): polygon points must be finite, got point 2=(1, inf, -1)");
}

} // TEST_SUITE
