// The doctest printers of support.hpp: a failing CHECK
// on a Vec4, Mat4, Plane or MatrixPair must show the numbers, rows first,
// in round-trip precision.
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;

TEST_SUITE("math") {

TEST_CASE("printers: Vec3, Vec4, Mat4 by rows, Plane, Close") {
    CHECK(doctest::toString(glm::vec3(1, -0.5f, 0)) == "(1, -0.5, 0)");
    // float in 9 significant digits, double in 17: enough to round-trip.
    CHECK(doctest::toString(glm::vec4(0.1f, 2, 3, 4)) == "(0.100000001, 2, 3, 4)");
    CHECK(doctest::toString(glm::dvec4(0.1, 2, 3, 4)) == "(0.10000000000000001, 2, 3, 4)");
    glm::mat4 m(1);
    m[3][0] = 7; // column 3, row 0: printed at the end of the FIRST row
    CHECK(doctest::toString(m) == "rows[(1, 0, 0, 7), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)]");
    CHECK(doctest::toString(Plane<double>(0, 0, -1, -1)) == "Plane(0, 0, -1, -1)");
    // (doctest prints enums as their integer before any StringMaker, so
    // tests name a DepthRange with INFO("depth=", frustum::to_string(d)).)
    CHECK(frustum::to_string(DepthRange::MinusOneToOne) == "minus_one_to_one");
    CHECK(doctest::toString(close_abs(glm::dvec4(1, 2, 3, 4), 0.5)) == "(1, 2, 3, 4) +- 0.5");
    // close() scales its tolerance by the largest |entry|.
    CHECK(doctest::toString(close(glm::dvec4(1, 2, 3, -4), 0.25)) == "(1, 2, 3, -4) +- 1");
}

TEST_CASE("printers: MatrixPair shows depth, winding, matrix and inverse") {
    // Box [0, 2] x [0, 4] x [-2, 0], ZeroToOne: sx = 1, sy = 0.5,
    // tx = ty = -1, clip z = -0.5 z_eye; inverse x = X + 1, y = 2 Y + 2,
    // z = -2 Z.
    const auto box = frustum::orthographic<double>(0, 2, 0, 4, 0, 2, DepthRange::ZeroToOne);
    REQUIRE(box.ok());
    CHECK(doctest::toString(*box) ==
          "MatrixPair{depth=zero_to_one flips_winding=false matrix=rows[(1, 0, 0, -1), (0, 0.5, 0, -1), "
          "(0, 0, -0.5, 0), (0, 0, 0, 1)] inverse=rows[(1, 0, 0, 1), (0, 2, 0, 2), (0, 0, -2, 0), (0, 0, 0, 1)]}");
    const auto reflected = frustum::reflect(*box, Plane<double>(1, 0, 0, 0));
    REQUIRE(reflected.ok());
    CHECK(std::string(doctest::toString(*reflected).c_str()).find("flips_winding=true") != std::string::npos);
}

TEST_CASE("tolerance helpers compare what they say") {
    // close(): within, at and beyond the tolerance; NaN never equal.
    CHECK(glm::dvec4(1, 2, 3, 4.4) == close_abs(glm::dvec4(1, 2, 3, 4), 0.5));
    CHECK_FALSE(glm::dvec4(1, 2, 3, 4.6) == close_abs(glm::dvec4(1, 2, 3, 4), 0.5));
    CHECK_FALSE(glm::dvec4(1, 2, std::nan(""), 4) == close_abs(glm::dvec4(1, 2, 3, 4), 1e9));
    // inverse_residual is 0 for an exact pair and grows with a bad entry.
    const glm::dmat4 a = from_rows<double>({2, 0, 0, 0}, {0, 4, 0, 0}, {0, 0, 1, 1}, {0, 0, 0, 1});
    const glm::dmat4 inv = from_rows<double>({0.5, 0, 0, 0}, {0, 0.25, 0, 0}, {0, 0, 1, -1}, {0, 0, 0, 1});
    CHECK(inverse_residual(a, inv) == 0);
    glm::dmat4 off = inv;
    off[3][2] = -1 + 1e-9;
    CHECK(inverse_residual(a, off) > 1e-10);
    // factor_between: the factor and its sign.
    const Factor f = factor_between(a, glm::dmat4(-3.0 * a));
    CHECK(f.lambda == doctest::Approx(-3).epsilon(mtest::tight<double>()));
    CHECK(f.residual <= 1e-15);
    // incidence: 0 on the plane, +-1 along the normal at infinity.
    CHECK(incidence(Plane<double>(0, 0, 1, -2), glm::dvec4(5, 7, 2, 1)) == 0);
    CHECK(incidence(Plane<double>(0, 0, 1, 0), glm::dvec4(0, 0, 3, 0)) == doctest::Approx(1).epsilon(mtest::tight<double>()));
}

} // TEST_SUITE
