// frustum-vectors, one test per camera kind: the printed pair against an
// independent construction (GLM's _ZO/_NO functions, hand-written limits,
// plane algebra), for every depth range.
#include "vectors_checks.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

using namespace vectors_test;

namespace {

constexpr double kPi = 3.14159265358979323846;

json one_case(const char* depth, json camera) {
    return json{{"id", "t"}, {"depth", depth}, {"camera", std::move(camera)}};
}

// A [0, 1] matrix for `d`: GLM's _NO form directly for [-1, 1], the _ZO form
// remapped otherwise (GLM has no reversed-Z factory).
glm::dmat4 expected_for(const DepthCase& d, const glm::dmat4& zo, const glm::dmat4& no) {
    return d.z_near == -1.0 ? no : remap_depth_from_zo(zo, d);
}

} // namespace

TEST_SUITE("cli") {

TEST_CASE("vectors: perspective with view equals glmPerspectiveRH * lookAtRH in every depth range") {
    const glm::dvec3 eye(0, 1, 5), target(0, 0, 0), up(0, 1, 0);
    const glm::dmat4 view = glm::lookAtRH(eye, target, up);
    const double fovy = 60 * kPi / 180;
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        json c = one_case(d.name, {{"perspective", {{"fovy_deg", 60}, {"aspect", 1.5}, {"near", 0.1}, {"far", 100}}}});
        c["view"] = {{"eye", {0, 1, 5}}, {"target", {0, 0, 0}}, {"up", {0, 1, 0}}};
        c["points"] = {{0, 0, 0}, {0, 0.5, -3}, {30, 0, 0}, {0, 1, 5}, {0, 0, -200}};
        const json a = answer(c);
        check_consistent(c, a);
        const glm::dmat4 p = expected_for(d, glm::perspectiveRH_ZO(fovy, 1.5, 0.1, 100.0),
                                          glm::perspectiveRH_NO(fovy, 1.5, 0.1, 100.0));
        CHECK(close(mat4(a["matrix"]), p * view));
        CHECK(close(mat4(a["inverse"]), glm::inverse(p * view), 1e-10));
        // Landmarks: the eye, and depth of points at near and far distance.
        CHECK(close(vec4(a["vanishing"]["O"]), glm::dvec4(eye, 1), 1e-12));
        const glm::dvec3 forward = glm::normalize(target - eye);
        const glm::dmat4 m = mat4(a["matrix"]);
        const glm::dvec4 at_near = m * glm::dvec4(eye + 0.1 * forward, 1);
        const glm::dvec4 at_far = m * glm::dvec4(eye + 100.0 * forward, 1);
        CHECK(at_near.z / at_near.w == doctest::Approx(d.z_near).epsilon(1e-12));
        CHECK(at_far.z / at_far.w == doctest::Approx(d.z_far).epsilon(1e-12));
        CHECK(a["valid"].get<bool>());
        CHECK(a["inside"] == json({true, true, false, false, false}));
    }
}

TEST_CASE("vectors: infinite perspective has a null far plane and far corners at infinity") {
    const double fovy = 75 * kPi / 180;
    const double n = 0.05;
    // Limits far -> infinity of perspectiveRH_ZO: m22 = -1, m32 = -n.
    glm::dmat4 zo = glm::perspectiveRH_ZO(fovy, 0.75, n, 1.0);
    zo[2][2] = -1;
    zo[3][2] = -n;
    const glm::dmat4 no = glm::infinitePerspectiveRH(fovy, 0.75, n); // GLM's infinite form is [-1, 1] only
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        json c = one_case(d.name, {{"perspective", {{"fovy_deg", 75}, {"aspect", 0.75}, {"near", n}, {"far", nullptr}}}});
        c["points"] = {{0, 0, -1}, {0, 0, -1e6}, {1e6, 0, -1e6}, {0, 0, 1}};
        const json a = answer(c);
        check_consistent(c, a);
        CHECK(close(mat4(a["matrix"]), expected_for(d, zo, no)));
        CHECK(a["planes"]["far"].is_null());
        for (int i = 4; i < 8; ++i) {
            const glm::dvec4 corner = vec4(a["corners"][static_cast<std::size_t>(i)]);
            CHECK(corner.w == 0.0);
            CHECK(corner.z < 0); // pointing forward, down -z
        }
        // A direction (w = 0) straight ahead lands on the far depth.
        const glm::dvec4 ahead = mat4(a["matrix"]) * glm::dvec4(0, 0, -1, 0);
        CHECK(ahead.z / ahead.w == doctest::Approx(d.z_far).epsilon(1e-12));
        CHECK(a["inside"] == json({true, true, false, false}));
    }
}

TEST_CASE("vectors: off-axis frustum equals glm frustumRH, finite and infinite") {
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        json c = one_case(d.name, {{"frustum", {{"left", -0.3}, {"right", 0.1}, {"bottom", -0.05}, {"top", 0.2},
                                                {"near", 0.25}, {"far", 40}}}});
        c["view"] = {{"eye", {3, -2, 4}}, {"target", {-1, 0.5, -2}}, {"up", {0.2, 1, 0.1}}};
        c["points"] = {{-1, 0.5, -2}, {3, -2, 4}};
        const json a = answer(c);
        check_consistent(c, a);
        const glm::dmat4 view = glm::lookAtRH(glm::dvec3(3, -2, 4), glm::dvec3(-1, 0.5, -2), glm::dvec3(0.2, 1, 0.1));
        const glm::dmat4 p = expected_for(d, glm::frustumRH_ZO(-0.3, 0.1, -0.05, 0.2, 0.25, 40.0),
                                          glm::frustumRH_NO(-0.3, 0.1, -0.05, 0.2, 0.25, 40.0));
        CHECK(close(mat4(a["matrix"]), p * view));
        // The near corners are the rectangle at z = -near in eye space.
        const glm::dmat4 view_inv = glm::inverse(view);
        CHECK(close(vec4(a["corners"][0]), view_inv * glm::dvec4(0.1, 0.2, -0.25, 1), 1e-12));
        CHECK(close(vec4(a["corners"][2]), view_inv * glm::dvec4(-0.3, -0.05, -0.25, 1), 1e-12));

        json inf = one_case(d.name, {{"frustum", {{"left", -1}, {"right", 2}, {"bottom", -1.5}, {"top", 0.5},
                                                  {"near", 1}, {"far", nullptr}}}});
        const json b = answer(inf);
        check_consistent(inf, b);
        glm::dmat4 zo = glm::frustumRH_ZO(-1.0, 2.0, -1.5, 0.5, 1.0, 2.0);
        zo[2][2] = -1; // far -> infinity
        zo[3][2] = -1; // -near
        glm::dmat4 no = glm::frustumRH_NO(-1.0, 2.0, -1.5, 0.5, 1.0, 2.0);
        no[2][2] = -1;
        no[3][2] = -2; // -2 near
        CHECK(close(mat4(b["matrix"]), expected_for(d, zo, no)));
        CHECK(b["planes"]["far"].is_null());
    }
}

TEST_CASE("vectors: ortho equals glm orthoRH; its eye is a direction pointing back") {
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        json c = one_case(d.name, {{"ortho", {{"left", -4}, {"right", 2}, {"bottom", -1}, {"top", 3}, {"near", -2}, {"far", 8}}}});
        c["points"] = {{0, 0, 0}, {0, 0, 1.9}, {0, 0, -7.9}, {0, 0, 2.1}, {-5, 0, -1}};
        const json a = answer(c);
        check_consistent(c, a);
        const glm::dmat4 p = expected_for(d, glm::orthoRH_ZO(-4.0, 2.0, -1.0, 3.0, -2.0, 8.0),
                                          glm::orthoRH_NO(-4.0, 2.0, -1.0, 3.0, -2.0, 8.0));
        CHECK(close(mat4(a["matrix"]), p));
        CHECK(close(mat4(a["inverse"]), glm::inverse(p)));
        CHECK(close(vec4(a["vanishing"]["O"]), glm::dvec4(0, 0, 1, 0)));
        CHECK(a["inside"] == json({true, true, true, false, false}));
        CHECK(a["valid"].get<bool>());
    }
}

TEST_CASE("vectors: planes camera reproduces its five planes and passes the far plane through far_point") {
    const json side = {{"left", {1, 0, -1, 0}}, {"right", {-1, 0, -1, 0}}, {"bottom", {0, 1, -1, 0}}, {"top", {0, -1, -1, 0}}};
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        json planes = side;
        planes["near"] = {0, 0, -2, -2}; // unnormalized on purpose
        planes["far_point"] = {0, 0, -10};
        json c = one_case(d.name, {{"planes", planes}});
        c["points"] = {{0, 0, -5}, {0, 0, -11}, {4, 0, -3}, {0, 0, -0.5}};
        const json a = answer(c);
        check_consistent(c, a);
        const double r = std::sqrt(0.5);
        CHECK(close(vec4(a["planes"]["left"]), glm::dvec4(r, 0, -r, 0)));
        CHECK(close(vec4(a["planes"]["top"]), glm::dvec4(0, -r, -r, 0)));
        CHECK(close(vec4(a["planes"]["near"]), glm::dvec4(0, 0, -1, -1)));
        CHECK(close(vec4(a["planes"]["far"]), glm::dvec4(0, 0, 1, 10)));
        CHECK(close(vec4(a["vanishing"]["O"]), glm::dvec4(0, 0, 0, 1)));
        // The same frustum as glm::frustumRH with l, r, b, t = -+1 at near 1, far 10, up to scale.
        const glm::dmat4 m = mat4(a["matrix"]);
        const glm::dmat4 reference =
            expected_for(d, glm::frustumRH_ZO(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0), glm::frustumRH_NO(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0));
        CHECK(close(m / m[2][3] * reference[2][3], reference));
        CHECK(a["inside"] == json({true, false, false, false}));
        CHECK(a["valid"].get<bool>());

        // §4.2 (erratum 12): a tilted near plane, far grown until every far
        // corner is a finite point in front of the eye.
        json grown = side;
        grown["near"] = {0.3, -0.2, -1, -1};
        grown["far"] = "volume";
        json g = one_case(d.name, {{"planes", grown}});
        const json b = answer(g);
        check_consistent(g, b);
        const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.2, -1));
        CHECK(close(vec4(b["planes"]["near"]), glm::dvec4(n, -1 / glm::length(glm::dvec3(0.3, -0.2, -1)))));
        for (int i = 4; i < 8; ++i) {
            const glm::dvec4 corner = vec4(b["corners"][static_cast<std::size_t>(i)]);
            CHECK(corner.w == 1.0);
            CHECK(corner.z < 0); // in front of the eye at the origin
        }
        CHECK(b["valid"].get<bool>());
    }
}

// The rectangle of the mirror_rect tests: a wall mirror in the plane
// z = -2 seen from (0.3, 1, 2); the reflected eye O' is (0.3, 1, -6).
json mirror_rect_case(const char* depth, const char* fit) {
    return one_case(depth, {{"mirror_rect", {{"corner", {-1, 0, -2}}, {"a1", {2, 0, 0}}, {"a2", {0, 1.5, 0}},
                                             {"eye", {0.3, 1, 2}}, {"far", 50}, {"fit", fit}}}});
}
const glm::dvec3 kRectangle[4] = {{-1, 0, -2}, {1, 0, -2}, {1, 1.5, -2}, {-1, 1.5, -2}};

// min over the rectangle's corners of the plane's value: 0 when the plane
// touches the rectangle, > 0 when the rectangle is strictly inside.
double lowest_on_rectangle(const glm::dvec4& plane) {
    double lowest = 1e300;
    for (const glm::dvec3& p : kRectangle) {
        lowest = std::min(lowest, glm::dot(plane, glm::dvec4(p, 1)));
    }
    return lowest;
}

TEST_CASE("vectors: mirror_rect exact fit: the near face is the mirror, seen from the reflected eye") {
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        json c = mirror_rect_case(d.name, "exact");
        c["points"] = {{0, 0.75, -3}, {0, 0.75, 0}, {0, 0.75, -2.5}, {0.1, 0.7, -1.9}};
        const json a = answer(c);
        check_consistent(c, a);
        CHECK(close(vec4(a["vanishing"]["O"]), glm::dvec4(0.3, 1, -6, 1), 1e-12));
        // O' looks through the mirror towards +z: inside is z > -2.
        CHECK(close(vec4(a["planes"]["near"]), glm::dvec4(0, 0, 1, 2)));
        for (int i = 0; i < 4; ++i) {
            const glm::dvec4 corner = vec4(a["corners"][static_cast<std::size_t>(i)]);
            bool on_rectangle = false;
            for (const glm::dvec3& p : kRectangle) {
                on_rectangle = on_rectangle || glm::length(glm::dvec3(corner) - p) < 1e-12;
            }
            CHECK(on_rectangle);
        }
        for (const char* side : {"left", "right", "bottom", "top"}) {
            INFO("side " << std::string(side));
            CHECK(std::abs(lowest_on_rectangle(vec4(a["planes"][side]))) < 1e-12); // tight
        }
        CHECK(a["inside"] == json({false, true, false, true}));
        CHECK(a["valid"].get<bool>());
    }
}

TEST_CASE("vectors: mirror_rect paper fit: axis through the centre, the rectangle inside the frustum") {
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        const json c = mirror_rect_case(d.name, "paper");
        const json a = answer(c);
        check_consistent(c, a);
        const glm::dvec3 reflected(0.3, 1, -6);
        CHECK(close(vec4(a["vanishing"]["O"]), glm::dvec4(reflected, 1), 1e-12));
        // The near plane is perpendicular to the axis O' -> C and passes
        // through the nearest corner (erratum 5: not the mirror's plane).
        const glm::dvec4 near = vec4(a["planes"]["near"]);
        const glm::dvec3 axis = glm::normalize(glm::dvec3(0, 0.75, -2) - reflected);
        CHECK(close(glm::dvec4(glm::dvec3(near), 0), glm::dvec4(axis, 0)));
        CHECK(std::abs(lowest_on_rectangle(near)) < 1e-12);
        for (const char* side : {"left", "right", "bottom", "top"}) {
            INFO("side " << std::string(side));
            CHECK(lowest_on_rectangle(vec4(a["planes"][side])) > -1e-12); // conservative
        }
        CHECK(a["valid"].get<bool>());
    }
}

// Regression: mirror_rectangle() once started the bounds l, r, b, t at the
// UNPROJECTED x[0], y[0] of corner P1, so with the paper fit (corners at
// different depths) left and bottom were too loose. The contract says
// l, r, b, t are the bounds of the projected corners, so every side plane
// must touch the rectangle.
TEST_CASE("vectors: mirror_rect paper fit: every side plane touches the rectangle") {
    const json a = answer(mirror_rect_case("zero_to_one", "paper"));
    for (const char* side : {"left", "right", "bottom", "top"}) {
        INFO("side " << std::string(side));
        CHECK(std::abs(lowest_on_rectangle(vec4(a["planes"][side]))) < 1e-12);
    }
}

TEST_CASE("vectors: matrix camera keeps the matrix, up to the sign convention") {
    const double f = 1 / std::tan(30 * kPi / 180);
    const glm::dmat4 glm_p = glm::perspectiveRH_ZO(60 * kPi / 180, 1.5, 0.1, 100.0);
    json numbers = json::array();
    for (int col = 0; col < 4; ++col) {
        for (int r = 0; r < 4; ++r) {
            numbers.push_back(glm_p[col][r]);
        }
    }
    json c = one_case("zero_to_one", {{"matrix", numbers}});
    const json a = answer(c);
    check_consistent(c, a);
    CHECK(mat4(a["matrix"]) == glm_p); // bit for bit: printed numbers round-trip
    CHECK(glm_p[1][1] == doctest::Approx(f).epsilon(1e-15)); // two roundings of tan apart

    // The negated matrix is the same projective map; the tool prints the
    // w > 0 representative, i.e. the matrix negated back.
    json negated = json::array();
    for (const auto& v : numbers) {
        negated.push_back(-v.get<double>());
    }
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        json n = one_case(d.name, {{"matrix", negated}});
        const json b = answer(n);
        check_consistent(n, b);
        const glm::dmat4 m = mat4(b["matrix"]);
        CHECK((m == glm_p || m == -glm_p));
    }
    const json b = answer(one_case("zero_to_one", {{"matrix", negated}}));
    CHECK(mat4(b["matrix"]) == glm_p);

    // A general invertible matrix: inverse against glm::inverse.
    json general = one_case("minus_one_to_one", {{"matrix", {1.2, 0.1, 0.3, 0.2, -0.2, 0.9, 0.1, -0.1, 0.05, 0.3, -1.1, -1,
                                                              0.4, -0.3, 0.2, 2.5}}});
    check_consistent(general, answer(general));
}

} // TEST_SUITE
