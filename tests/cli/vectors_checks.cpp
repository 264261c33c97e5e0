#include "vectors_checks.hpp"

#include <algorithm>
#include <optional>
#include <string>

namespace vectors_test {

namespace {

glm::dvec4 row(const glm::dmat4& m, int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); }

double plane_value(const glm::dvec4& plane, const glm::dvec4& point) {
    // A finite point (w = 1) gives the signed distance; a direction (w = 0)
    // gives the cosine with the normal.
    return glm::dot(plane, point);
}

// Indices (0-based) of the corners on each face, eq. 8 order:
// C1 (1,1) C2 (-1,1) C3 (-1,-1) C4 (1,-1), near then far.
constexpr int kFaceCorners[6][4] = {
    {1, 2, 5, 6}, // left:   x = -1
    {0, 3, 4, 7}, // right:  x = +1
    {2, 3, 6, 7}, // bottom: y = -1
    {0, 1, 4, 5}, // top:    y = +1
    {0, 1, 2, 3}, // near
    {4, 5, 6, 7}, // far
};
constexpr const char* kFaceNames[6] = {"left", "right", "bottom", "top", "near", "far"};

} // namespace

const DepthCase& depth_of(const json& request_case) {
    const std::string name = request_case.value("depth", std::string("zero_to_one"));
    for (const DepthCase& d : kDepths) {
        if (name == d.name) {
            return d;
        }
    }
    FAIL("unknown depth " << name);
    return kDepths[0];
}

void check_consistent(const json& request_case, const json& a) {
    INFO("case " << a["id"].get<std::string>() << ", depth " << std::string(depth_of(request_case).name));
    const DepthCase& d = depth_of(request_case);
    const double s = d.z_far > d.z_near ? 1.0 : -1.0;
    const glm::dmat4 m = mat4(a["matrix"]);
    const glm::dmat4 inv = mat4(a["inverse"]);
    const glm::dmat4 reference_inv = glm::inverse(m);
    INFO("matrix\n" << to_text(m) << "\ninverse\n" << to_text(inv) << "\nglm::inverse\n" << to_text(reference_inv));
    CHECK(close(inv, reference_inv, 1e-9));
    CHECK(close(m * inv, glm::dmat4(1.0), 1e-9));

    // Sign convention: w > 0 just inside the centre of the near face.
    const glm::dvec4 inside_near = inv * glm::dvec4(0, 0, d.z_near + 0.01 * (d.z_far - d.z_near), 1);
    CHECK(inside_near.w > 0);

    // Planes: unit, and the normalized rows combinations (eq. 1, erratum 11).
    const glm::dvec4 m0 = row(m, 0), m1 = row(m, 1), m2 = row(m, 2), m3 = row(m, 3);
    const glm::dvec4 raw[6] = {m3 + m0, m3 - m0, m3 + m1, m3 - m1, s * (m2 - d.z_near * m3), s * (d.z_far * m3 - m2)};
    std::optional<glm::dvec4> planes[6];
    for (int f = 0; f < 6; ++f) {
        INFO("plane " << std::string(kFaceNames[f]));
        const json& p = a["planes"][kFaceNames[f]];
        if (f == 5 && p.is_null()) {
            // Infinite far plane: its raw normal vanishes.
            CHECK(glm::length(glm::dvec3(raw[5])) <= 1e-9 * (glm::length(glm::dvec3(m3)) + glm::length(glm::dvec3(m2))));
            continue;
        }
        planes[f] = vec4(p);
        CHECK(std::abs(glm::length(glm::dvec3(*planes[f])) - 1.0) < 1e-12);
        CHECK(close(*planes[f], raw[f] / glm::length(glm::dvec3(raw[f])), 1e-9));
    }

    // Corners, centre, vanishing points: canonical unprojections.
    glm::dvec4 corners[8];
    for (int i = 0; i < 8; ++i) {
        INFO("corner C" << i + 1);
        corners[i] = vec4(a["corners"][static_cast<std::size_t>(i)]);
        CHECK(close(corners[i], canonical(reference_inv * clip_corner(i, d.z_near, d.z_far)), 1e-8));
        CHECK((corners[i].w == 1.0 || (corners[i].w == 0.0 && std::abs(glm::length(glm::dvec3(corners[i])) - 1) < 1e-12)));
    }
    const glm::dvec4 center = vec4(a["center"]);
    CHECK(close(center, canonical(reference_inv * glm::dvec4(0, 0, (d.z_near + d.z_far) / 2, 1)), 1e-8));
    CHECK(close(vec4(a["vanishing"]["O1"]), canonical(reference_inv[1]), 1e-8));
    CHECK(close(vec4(a["vanishing"]["O2"]), canonical(reference_inv[0]), 1e-8));
    const glm::dvec4 eye = vec4(a["vanishing"]["O"]);
    const glm::dvec4 eye_column = canonical(reference_inv[2]);
    CHECK((close(eye, eye_column, 1e-8) || close(eye, -eye_column, 1e-8) ||
           close(eye, glm::dvec4(-glm::dvec3(eye_column), eye_column.w), 1e-8)));
    if (a["valid"].get<bool>()) {
        CHECK(plane_value(*planes[4], eye) < 0); // the eye is behind the near plane
    }

    // Each face's corners lie on its plane; the centre is inside all of them.
    for (int f = 0; f < 6; ++f) {
        if (!planes[f]) {
            continue;
        }
        for (int k = 0; k < 4; ++k) {
            const glm::dvec4& c = corners[kFaceCorners[f][k]];
            INFO("face " << std::string(kFaceNames[f]) << ", corner C" << kFaceCorners[f][k] + 1);
            const double scale = c.w == 1.0 ? 1.0 + glm::length(glm::dvec3(c)) + std::abs(planes[f]->w) : 1.0;
            CHECK(std::abs(plane_value(*planes[f], c)) <= 1e-8 * scale);
        }
        // D is inside a valid frustum; after an oblique clip it can fall
        // behind the eye (the contract says so).
        if (center.w == 1.0 && a["valid"].get<bool>()) {
            CHECK(plane_value(*planes[f], center) > 0);
        }
    }

    // Points: clip coordinates and the inside flag.
    if (!request_case.contains("points")) {
        CHECK_FALSE(a.contains("clip"));
        CHECK_FALSE(a.contains("inside"));
        return;
    }
    const json& points = request_case["points"];
    REQUIRE(a["clip"].size() == points.size());
    REQUIRE(a["inside"].size() == points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        INFO("point " << i);
        const glm::dvec4 p(points[i][0].get<double>(), points[i][1].get<double>(), points[i][2].get<double>(), 1.0);
        const glm::dvec4 clip = m * p;
        CHECK(close(vec4(a["clip"][i]), clip, 1e-12));
        // Clip-space test: w > 0, |x|, |y| <= w, z between the depth bounds.
        double margin = std::min({clip.w + clip.x, clip.w - clip.x, clip.w + clip.y, clip.w - clip.y,
                                  s * (clip.z - d.z_near * clip.w)});
        if (!a["planes"]["far"].is_null()) {
            margin = std::min(margin, s * (d.z_far * clip.w - clip.z));
        }
        const double scale = glm::length(clip);
        if (margin > 1e-4 * scale) {
            CHECK(a["inside"][i].get<bool>());
        } else if (margin < -1e-4 * scale) {
            CHECK_FALSE(a["inside"][i].get<bool>());
        }
    }
}

} // namespace vectors_test
