// frustum-vectors ops (paper §5): crop, reflect, clip, mirror, each against
// an independent construction with GLM, in every depth range.
#include "vectors_checks.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

using namespace vectors_test;

namespace {

glm::dvec4 row(const glm::dmat4& m, int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); }

// The view1 perspective of the contract's example: 60 deg, 1.5, 0.1..100,
// from (0, 1, 5) towards the origin.
json base_case(const char* depth, json ops, json far = 100) {
    return json{{"id", "op"},
                {"depth", depth},
                {"camera", {{"perspective", {{"fovy_deg", 60}, {"aspect", 1.5}, {"near", 0.1}, {"far", far}}}}},
                {"view", {{"eye", {0, 1, 5}}, {"target", {0, 0, 0}}, {"up", {0, 1, 0}}}},
                {"ops", std::move(ops)}};
}

// The clip-space map of a crop (x, y offset from the bottom-left): the
// rectangle's NDC range [x0, x1] goes to [-1, 1], x' = (2 x - (x0 + x1) w) / (x1 - x0).
glm::dmat4 crop_map(double x, double y, double width, double height, double full_width, double full_height) {
    const double x0 = -1 + 2 * x / full_width, x1 = -1 + 2 * (x + width) / full_width;
    const double y0 = -1 + 2 * y / full_height, y1 = -1 + 2 * (y + height) / full_height;
    glm::dmat4 s(1.0);
    s[0][0] = 2 / (x1 - x0);
    s[3][0] = -(x0 + x1) / (x1 - x0);
    s[1][1] = 2 / (y1 - y0);
    s[3][1] = -(y0 + y1) / (y1 - y0);
    return s;
}

// eq. 16 for a normalized plane (n, d): p -> p - 2 (n . p + d) n.
glm::dmat4 reflection(const glm::dvec4& plane) {
    const glm::dvec3 n = glm::dvec3(plane) / glm::length(glm::dvec3(plane));
    const double d = plane.w / glm::length(glm::dvec3(plane));
    glm::dmat4 r(1.0);
    for (int c = 0; c < 3; ++c) {
        for (int k = 0; k < 3; ++k) {
            r[c][k] -= 2 * n[k] * n[c];
        }
    }
    r[3] = glm::dvec4(-2 * d * n, 1);
    return r;
}

glm::dvec4 unit(const glm::dvec4& plane) { return plane / glm::length(glm::dvec3(plane)); }

} // namespace

TEST_SUITE("cli") {

TEST_CASE("vectors: crop is the clip-space rectangle map, offset from the bottom-left") {
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        const json plain = answer(base_case(d.name, json::array()));
        const glm::dmat4 m = mat4(plain["matrix"]);

        json c = base_case(d.name, {{{"crop", {{"x", 0}, {"y", 0}, {"width", 640}, {"height", 360},
                                               {"full_width", 1280}, {"full_height", 720}}}}});
        // The bottom-left quarter of the image: a point seen at NDC
        // (-0.5, -0.5) is inside, one at (+0.5, -0.5) or (-0.5, +0.5) is not.
        const glm::dmat4 inv = glm::inverse(m);
        json points = json::array();
        for (const glm::dvec2 ndc : {glm::dvec2(-0.5, -0.5), glm::dvec2(0.5, -0.5), glm::dvec2(-0.5, 0.5)}) {
            const glm::dvec4 p = canonical(inv * glm::dvec4(ndc, (d.z_near + d.z_far) / 2, 1));
            points.push_back({p.x, p.y, p.z});
        }
        c["points"] = points;
        const json a = answer(c);
        check_consistent(c, a);
        CHECK(close(mat4(a["matrix"]), crop_map(0, 0, 640, 360, 1280, 720) * m));
        CHECK(a["inside"] == json({true, false, false}));
        // Rows 2 and 3 (depth and w) are untouched: crop works for every depth range.
        CHECK(close(row(mat4(a["matrix"]), 2), row(m, 2)));
        CHECK(close(row(mat4(a["matrix"]), 3), row(m, 3)));

        // Two crops compose: a sub-rectangle of a sub-rectangle.
        json twice = base_case(d.name, {{{"crop", {{"x", 0}, {"y", 0}, {"width", 640}, {"height", 360},
                                                   {"full_width", 1280}, {"full_height", 720}}}},
                                        {{"crop", {{"x", 0.25}, {"y", 0.5}, {"width", 0.5}, {"height", 0.25},
                                                   {"full_width", 1}, {"full_height", 1}}}}});
        const json b = answer(twice);
        check_consistent(twice, b);
        CHECK(close(mat4(b["matrix"]), crop_map(160, 180, 320, 90, 1280, 720) * m));
    }
}

TEST_CASE("vectors: reflect is M R with R the reflection in the plane (any side, any scale)") {
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        const glm::dmat4 m = mat4(answer(base_case(d.name, json::array()))["matrix"]);
        for (const glm::dvec4 plane : {glm::dvec4(0, 1, 0, 0), glm::dvec4(0, -2, 0, 0), glm::dvec4(1, 0.5, -0.2, 3)}) {
            INFO("plane " << plane.x << " " << plane.y << " " << plane.z << " " << plane.w);
            json c = base_case(d.name, {{{"reflect", {{"plane", {plane.x, plane.y, plane.z, plane.w}}}}}});
            c["points"] = {{0, -0.5, -3}, {0, 0.5, -3}};
            const json a = answer(c);
            check_consistent(c, a);
            const glm::dmat4 r = reflection(plane);
            CHECK(close(mat4(a["matrix"]), m * r));
            CHECK(close(vec4(a["vanishing"]["O"]), r * glm::dvec4(0, 1, 5, 1), 1e-12));
            CHECK(a["valid"].get<bool>());
        }
    }
}

TEST_CASE("vectors: clip makes the plane the near plane and keeps the side planes") {
    for (const DepthCase& d : kDepths) {
        for (const json& far : {json(100), json(nullptr)}) {
            INFO("depth " << std::string(d.name) << ", far " << far.dump());
            const json plain = answer(base_case(d.name, json::array(), far));
            const glm::dvec4 plane(0, 0, -2, 2); // z <= 1 stays visible; the eye (z = 5) is on the negative side
            json c = base_case(d.name, {{{"clip", {{"plane", {0, 0, -2, 2}}}}}}, far);
            c["points"] = {{0, 0, 0}, {0, 0, 2}, {0, 0.9, 1.2}};
            const json a = answer(c);
            check_consistent(c, a);
            CHECK(close(vec4(a["planes"]["near"]), unit(plane)));
            for (const char* side : {"left", "right", "bottom", "top"}) {
                INFO("side " << std::string(side));
                CHECK(close(vec4(a["planes"][side]), vec4(plain["planes"][side])));
            }
            // Rows 0, 1 and 3 of M are kept (eq. 22: only the third row changes).
            const glm::dmat4 m = mat4(a["matrix"]), m_plain = mat4(plain["matrix"]);
            for (int i : {0, 1, 3}) {
                CHECK(close(row(m, i), row(m_plain, i)));
            }
            // The new far plane is finite and passes through a far corner of
            // the original frustum (erratum 2: the clip-space corner Q).
            REQUIRE_FALSE(a["planes"]["far"].is_null());
            const glm::dvec4 far_plane = vec4(a["planes"]["far"]);
            double nearest = 1e300;
            for (int i = 4; i < 8; ++i) {
                const glm::dvec4 corner = vec4(plain["corners"][static_cast<std::size_t>(i)]);
                nearest = std::min(nearest, std::abs(glm::dot(far_plane, corner)) /
                                                (corner.w == 1.0 ? 1.0 + glm::length(glm::dvec3(corner)) : 1.0));
            }
            CHECK(nearest < 1e-9);
            CHECK(a["inside"] == json({true, false, false}));
        }
    }
}

TEST_CASE("vectors: mirror equals reflect then clip by the same plane") {
    for (const DepthCase& d : kDepths) {
        for (const json& far : {json(100), json(nullptr)}) {
            INFO("depth " << std::string(d.name) << ", far " << far.dump());
            const json plane = {0, 2, 0, 0.5}; // a floor at y = -0.25, seen from above
            json mirror = base_case(d.name, {{{"mirror", {{"plane", plane}}}}}, far);
            mirror["points"] = {{0, -0.5, 0}, {0, 0.5, 0}, {0, 0.3, -0.2}};
            json two_steps = base_case(d.name, {{{"reflect", {{"plane", plane}}}}, {{"clip", {{"plane", plane}}}}}, far);
            const json a = answer(mirror);
            const json b = answer(two_steps);
            check_consistent(mirror, a);
            CHECK(close(mat4(a["matrix"]), mat4(b["matrix"]), 1e-12));
            CHECK(close(mat4(a["inverse"]), mat4(b["inverse"]), 1e-10));
            CHECK(close(vec4(a["planes"]["near"]), unit(glm::dvec4(0, 2, 0, 0.5))));
            CHECK(close(vec4(a["vanishing"]["O"]), glm::dvec4(0, -1.5, 5, 1), 1e-12)); // the eye (0, 1, 5) reflected
            CHECK(a["inside"] == json({false, true, true}));
        }
    }
}

TEST_CASE("vectors: clip on an orthographic frustum and ops after a planes camera") {
    json ortho = {{"id", "o"},
                  {"camera", {{"ortho", {{"left", -1}, {"right", 1}, {"bottom", -1}, {"top", 1}, {"near", 0}, {"far", 10}}}}},
                  {"ops", {{{"clip", {{"plane", {0.1, 0, -1, -2}}}}}}},
                  {"points", {{0, 0, -1}, {0, 0, -3}}}};
    const json a = answer(ortho);
    check_consistent(ortho, a);
    CHECK(close(vec4(a["planes"]["near"]), unit(glm::dvec4(0.1, 0, -1, -2))));
    CHECK(a["inside"] == json({false, true}));

    json planes = {{"id", "p"},
                   {"depth", "reversed_zero_to_one"},
                   {"camera", {{"planes", {{"left", {1, 0, -1, 0}}, {"right", {-1, 0, -1, 0}}, {"bottom", {0, 1, -1, 0}},
                                           {"top", {0, -1, -1, 0}}, {"near", {0, 0, -1, -1}}, {"far_point", {0, 0, -10}}}}}},
                   {"ops", {{{"crop", {{"x", 1}, {"y", 2}, {"width", 1}, {"height", 1}, {"full_width", 3}, {"full_height", 3}}}},
                            {{"reflect", {{"plane", {1, 0, 0, 0}}}}}}}};
    const json b = answer(planes);
    check_consistent(planes, b);
}

} // TEST_SUITE
