// Helpers for the frustum-vectors tests: run the tool in-process on a
// request, read the response back, and build independent expectations.
#pragma once

#include "vectors/run.hpp"

#include <doctest/doctest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

namespace vectors_test {

using nlohmann::json;

struct Run {
    int status = -1;
    std::string out, err;
};

inline Run run_text(const std::string& request) {
    std::istringstream in(request);
    std::ostringstream out, err;
    Run r;
    r.status = vectors::run_frustum_vectors(in, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

// Runs a well-formed request and returns the parsed response.
inline json run_ok(const json& request) {
    const Run r = run_text(request.dump());
    REQUIRE_MESSAGE(r.status == 0, r.err);
    CHECK(r.err.empty());
    return json::parse(r.out);
}

// The single case of a one-case request; REQUIREs ok: true.
inline json answer(const json& one_case) {
    const json response = run_ok(json{{"cases", json::array({one_case})}});
    REQUIRE(response["cases"].size() == 1);
    const json c = response["cases"][0];
    REQUIRE_MESSAGE(c["ok"].get<bool>(), c.value("error", std::string()));
    return c;
}

// The error of a one-case request that must fail with ok: false.
inline std::string case_error(const json& one_case) {
    const json response = run_ok(json{{"cases", json::array({one_case})}});
    REQUIRE(response["cases"].size() == 1);
    const json c = response["cases"][0];
    REQUIRE_FALSE(c["ok"].get<bool>());
    CHECK(c.size() == 3); // id, ok, error only
    return c["error"].get<std::string>();
}

// A malformed request: exit 2, empty stdout; returns the stderr line.
inline std::string rejected(const std::string& request) {
    const Run r = run_text(request);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("frustum-vectors: ", 0) == 0);
    return r.err;
}

inline glm::dmat4 mat4(const json& a) {
    REQUIRE(a.size() == 16);
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            m[c][r] = a[static_cast<std::size_t>(4 * c + r)].get<double>();
        }
    }
    return m;
}

inline glm::dvec4 vec4(const json& a) {
    REQUIRE(a.is_array());
    REQUIRE(a.size() == 4);
    return glm::dvec4(a[0].get<double>(), a[1].get<double>(), a[2].get<double>(), a[3].get<double>());
}

inline double max_abs(const glm::dmat4& m) {
    double s = 0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            s = std::max(s, std::abs(m[c][r]));
        }
    }
    return s;
}

// |a - b| <= tol * max|entry of b| entrywise (a scale-relative comparison).
inline bool close(const glm::dmat4& a, const glm::dmat4& b, double tol = 1e-12) {
    const double scale = std::max(max_abs(b), 1e-300);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!(std::abs(a[c][r] - b[c][r]) <= tol * scale)) {
                return false;
            }
        }
    }
    return true;
}

inline bool close(const glm::dvec4& a, const glm::dvec4& b, double tol = 1e-12) {
    const double scale = std::max({std::abs(b.x), std::abs(b.y), std::abs(b.z), std::abs(b.w), 1.0});
    return glm::length(a - b) <= tol * scale;
}

// The canonical homogeneous form the contract prints: w = 1 or a unit direction.
inline glm::dvec4 canonical(const glm::dvec4& h) {
    const glm::dvec3 xyz(h);
    if (std::abs(h.w) > 1e-12 * glm::length(xyz) && h.w != 0.0) {
        return glm::dvec4(xyz / h.w, 1.0);
    }
    return glm::dvec4(glm::normalize(xyz), 0.0);
}

// Clip-space corner i (0-based) in the paper's order (eq. 8) for a depth range.
inline glm::dvec4 clip_corner(int i, double z_near, double z_far) {
    static constexpr double xs[4] = {1, -1, -1, 1};
    static constexpr double ys[4] = {1, 1, -1, -1};
    return glm::dvec4(xs[i % 4], ys[i % 4], i < 4 ? z_near : z_far, 1.0);
}

inline std::string to_text(const glm::dmat4& m) {
    std::ostringstream s;
    s.precision(17);
    for (int r = 0; r < 4; ++r) {
        s << (r ? "\n" : "") << "| " << m[0][r] << " " << m[1][r] << " " << m[2][r] << " " << m[3][r] << " |";
    }
    return s.str();
}

struct DepthCase {
    const char* name;
    double z_near, z_far;
};
inline constexpr std::array<DepthCase, 3> kDepths = {
    DepthCase{"zero_to_one", 0.0, 1.0}, DepthCase{"minus_one_to_one", -1.0, 1.0},
    DepthCase{"reversed_zero_to_one", 1.0, 0.0}};

// A [0, 1] matrix remapped to another depth range: z' = a z + b w with
// z_near = b, z_far = a + b (so reversed is z' = w - z, [-1, 1] is 2z - w).
inline glm::dmat4 remap_depth_from_zo(const glm::dmat4& zo, const DepthCase& d) {
    glm::dmat4 m = zo;
    const double a = d.z_far - d.z_near, b = d.z_near;
    for (int c = 0; c < 4; ++c) {
        m[c][2] = a * zo[c][2] + b * zo[c][3];
    }
    return m;
}

} // namespace vectors_test
