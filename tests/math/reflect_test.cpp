// reflect() and reflection_matrix() (paper §5.2 first step, eq. 16).
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("reflection_matrix: literal for the plane y = 2, involution, determinant -1", T, float, double) {
    // Unit plane c = (0, 1, 0, -2). Eq. 16 in column form: the 3x3 block
    // I - 2 n n^T = diag(1, -1, 1), translation -2 d n = (0, 4, 0):
    // y -> 4 - y.
    const Mat4<T> r = frustum::reflection_matrix(Plane<T>(0, 1, 0, -2));
    CHECK(r == from_rows<T>({1, 0, 0, 0}, {0, -1, 0, 4}, {0, 0, 1, 0}, {0, 0, 0, 1}));
    CHECK(Vec4<T>(r * Vec4<T>(3, 5, 7, 1)) == Vec4<T>(3, -1, 7, 1));

    Random rng(81);
    for (int i = 0; i < 500; ++i) {
        const glm::dvec3 n = rng.unit_vector();
        const Plane<T> plane(Vec4<T>(glm::dvec4(n, rng.uniform(-20, 20))));
        const Mat4<T> m = frustum::reflection_matrix(plane);
        // R R = I: entries up to ~40 (2|d|), so 40 * tight absolute.
        CHECK(Mat4<T>(m * m) == close_abs(Mat4<T>(1), 40 * tight<T>()));
        CHECK(glm::determinant(glm::dmat4(m)) == doctest::Approx(-1).epsilon(1e-5));
        // Points on the plane are fixed; the normal flips.
        const glm::dvec3 on = n * -double(plane.offset()) + glm::cross(n, rng.unit_vector()) * 3.0;
        const Vec4<T> fixed(Vec3<T>(on), 1);
        CHECK(Vec4<T>(m * fixed) == close_abs(fixed, 40 * tight<T>()));
        CHECK(Vec4<T>(m * Vec4<T>(plane.normal(), 0)) == close_abs(Vec4<T>(-plane.normal(), 0), tight<T>()));
    }
}

TEST_CASE_TEMPLATE("reflect: M' = M R (the paper's R P transposed), twice is the identity, winding toggles", T, float,
                   double) {
    for_each_random_camera<T>(82, 1000, [&](Random& rng, const CameraSpec& c, const MatrixPair<T>& pair) {
        // Any plane, either side facing the eye; unnormalized on purpose.
        const double scale = rng.uniform(0.1, 10);
        const double offset = rng.uniform(-30, 30) * scale; // drawn before the normal, as always
        const glm::dvec3 normal = rng.unit_vector() * scale;
        const Plane<T> plane(Vec4<T>(glm::dvec4(normal, offset)));
        const auto once = frustum::reflect(pair, plane);
        REQUIRE_MESSAGE(once.ok(), once.error());
        CHECK(once->flips_winding());
        CHECK(once->depth() == c.depth);
        const Mat4<T> r = frustum::reflection_matrix(plane.normalized());
        CHECK(column_relative_diff(once->matrix(), Mat4<T>(pair.matrix() * r)) <= loose<T>());
        CHECK(column_relative_diff(once->inverse(), Mat4<T>(r * pair.inverse())) <= loose<T>());
        CHECK(inverse_residual(*once) <= 256 * eps<T>());
        // The reflected pair maps R p exactly like the original maps p.
        const glm::dvec4 p = glm::dmat4(pair.inverse()) * random_clip_point(rng, c.depth, 0.01);
        const glm::dvec4 a = glm::dmat4(once->matrix()) * (glm::dmat4(r) * p);
        const glm::dvec4 b = glm::dmat4(pair.matrix()) * p;
        CHECK(a == close(b, loose<T>()));
        // Twice: the original pair and winding.
        const auto twice = frustum::reflect(*once, plane);
        REQUIRE(twice.ok());
        CHECK_FALSE(twice->flips_winding());
        CHECK(column_relative_diff(twice->matrix(), pair.matrix()) <= loose<T>());
        CHECK(column_relative_diff(twice->inverse(), pair.inverse()) <= loose<T>());
        // The reflected frustum's planes are the reflected planes (the
        // frustum is a mirror image, inward normals stay inward).
        const auto p0 = frustum::planes(pair);
        const auto p1 = frustum::planes(*once);
        const glm::dmat4 rd(r);
        const glm::dvec4 left_reflected = glm::transpose(rd) * glm::dvec4(p0.left.abcd); // c R^-1 = c R
        CHECK(glm::dvec4(p1.left.abcd) == close_abs(left_reflected, loose<T>() * (1 + max_abs(left_reflected))));
    });
}

TEST_CASE_TEMPLATE("reflect: the landmark in the plane z = -5 looks back at the origin", T, float, double) {
    // Eye (0, 0, 0) reflected in z = -5 is (0, 0, -10); the view axis -z
    // becomes +z; the near face (z = -1) becomes z = -9.
    const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), DepthRange::MinusOneToOne);
    REQUIRE(base.ok());
    const auto once = frustum::reflect(*base, Plane<T>(0, 0, 2, 10)); // unnormalized z = -5
    REQUIRE(once.ok());
    const auto k = frustum::key_points(*once);
    CHECK(frustum::to_point(k.eye, T(1e-6)) == close_abs(Vec4<T>(0, 0, -10, 1), loose<T>()));
    CHECK(frustum::to_point(k.corners[0], T(1e-6)) == close_abs(Vec4<T>(1, 1, -9, 1), loose<T>()));
    CHECK(frustum::to_point(k.corners[4], T(1e-6)) == close_abs(Vec4<T>(10, 10, 0, 1), loose<T>() * 10));
    CHECK(frustum::planes(*once).near == close_abs(Plane<T>(0, 0, 1, 9), tight<T>()));
    CHECK(frustum::validate(*once).valid());
}

} // TEST_SUITE
