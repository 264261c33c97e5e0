// frustum-vectors version 2 (shared spec "Version 2"): op jitter, op
// portal, case-level rects -> screen_rects and boxes -> cull, each checked
// against an independent construction with GLM, and their errors.
#include "vectors_checks.hpp"

using namespace vectors_test;

namespace {

glm::dvec4 row(const glm::dmat4& m, int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); }

json camera_case(const char* depth, json ops) {
    return json{{"id", "v2"},
                {"depth", depth},
                {"camera", {{"perspective", {{"fovy_deg", 60}, {"aspect", 1.5}, {"near", 0.1}, {"far", 100}}}}},
                {"view", {{"eye", {0, 1, 5}}, {"target", {0, 1, 0}}, {"up", {0, 1, 0}}}},
                {"ops", std::move(ops)}};
}

json frame(glm::dvec3 origin, glm::dvec3 x, glm::dvec3 y) {
    return json{{"origin", {origin.x, origin.y, origin.z}}, {"x", {x.x, x.y, x.z}}, {"y", {y.x, y.y, y.z}}};
}

// F: columns (x, 0), (y, 0), (x × y, 0), (origin, 1).
glm::dmat4 frame_matrix(glm::dvec3 origin, glm::dvec3 x, glm::dvec3 y) {
    return glm::dmat4(glm::dvec4(x, 0), glm::dvec4(y, 0), glm::dvec4(glm::cross(x, y), 0), glm::dvec4(origin, 1));
}

double max_diff(const glm::dvec4& a, const glm::dvec4& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z), std::abs(a.w - b.w)});
}

// The world-space square quad z = -2, [-1, 1]^2, seen by a 90 degree camera at the origin.
json square_case(json rects, json boxes) {
    json c{{"id", "sq"}, {"camera", {{"perspective", {{"fovy_deg", 90}, {"aspect", 1}, {"near", 1}, {"far", 10}}}}}};
    if (!rects.is_null()) c["rects"] = std::move(rects);
    if (!boxes.is_null()) c["boxes"] = std::move(boxes);
    return c;
}

} // namespace

TEST_SUITE("cli") {

TEST_CASE("vectors v2: jitter is J * M with 2 dx / W in row 0, column 3 and 2 dy / H in row 1, column 3") {
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        const glm::dmat4 m = mat4(answer(camera_case(d.name, json::array()))["matrix"]);
        const json j = answer(camera_case(
            d.name, json::array({{{"jitter", {{"dx", 0.25}, {"dy", -0.5}, {"full_width", 1280}, {"full_height", 720}}}}})));
        glm::dmat4 jm(1.0);
        jm[3][0] = 2 * 0.25 / 1280;
        jm[3][1] = 2 * -0.5 / 720;
        const glm::dmat4 expected = jm * m;
        const glm::dmat4 got = mat4(j["matrix"]);
        for (int i = 0; i < 4; ++i) {
            CHECK(max_diff(row(got, i), row(expected, i)) <= 1e-12 * (1 + std::abs(row(expected, i).w)));
        }
        const glm::dmat4 product = got * mat4(j["inverse"]);
        for (int c = 0; c < 4; ++c) CHECK(max_diff(product[c], glm::dmat4(1.0)[c]) <= 1e-10);
    }
}

TEST_CASE("vectors v2: portal's x, y, w rows are those of M F_entry H F_exit^-1; near plane = exit plane") {
    const glm::dvec3 eo(0, 1, 0), ex(1, 0, 0), ey(0, 1, 0);
    const glm::dvec3 xo(10, 1, -3), xx(0, 0, -1), xy(0, 1, 0);
    for (const DepthCase& d : kDepths) {
        INFO("depth " << std::string(d.name));
        const glm::dmat4 m = mat4(answer(camera_case(d.name, json::array()))["matrix"]);
        const json p = answer(camera_case(
            d.name, json::array({{{"portal", {{"entry", frame(eo, ex, ey)}, {"exit", frame(xo, xx, xy)}}}}})));
        const glm::dmat4 h(glm::dvec4(-1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, -1, 0),
                           glm::dvec4(0, 0, 0, 1));
        const glm::dmat4 carried = m * frame_matrix(eo, ex, ey) * h * glm::inverse(frame_matrix(xo, xx, xy));
        const glm::dmat4 got = mat4(p["matrix"]);
        // Row 2 is the oblique clip's; rows 0, 1, 3 are the carried camera's (same scale: clip keeps w).
        for (const int i : {0, 1, 3}) {
            CHECK(max_diff(row(got, i), row(carried, i)) <= 1e-9 * (1 + max_diff(row(carried, i), glm::dvec4(0))));
        }
        const json near = p["planes"]["near"];
        CHECK(std::abs(near[0].get<double>() - 1) <= 1e-9);
        CHECK(std::abs(near[3].get<double>() + 10) <= 1e-9);
        // Virtual eye 5 behind the exit: (5, 1, -3).
        const json eye = p["vanishing"]["O"];
        CHECK(std::abs(eye[0].get<double>() - 5) <= 1e-9);
        CHECK(std::abs(eye[1].get<double>() - 1) <= 1e-9);
        CHECK(std::abs(eye[2].get<double>() + 3) <= 1e-9);
    }
}

TEST_CASE("vectors v2: screen_rects, literal: a centred quad, a quad crossing the eye plane, nothing visible") {
    const json a = answer(square_case(
        json::array({{{"corners", {{-1, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-1, 1, -2}}}, {"full_width", 100}, {"full_height", 100}},
                     {{"corners", {{-1, -1, -3}, {1, -1, -3}, {1, -1, 3}, {-1, -1, 3}}}, {"full_width", 100}, {"full_height", 100}},
                     {{"corners", {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}}}, {"full_width", 100}, {"full_height", 100}}}),
        nullptr));
    const json r = a["screen_rects"];
    REQUIRE(r.size() == 3);
    CHECK(std::abs(r[0]["x"].get<double>() - 25) <= 1e-9);
    CHECK(std::abs(r[0]["width"].get<double>() - 50) <= 1e-9);
    CHECK(std::abs(r[1]["y"].get<double>()) <= 1e-9);
    CHECK(std::abs(r[1]["height"].get<double>() - 100.0 / 3) <= 1e-9); // not 66.7: no point behind the eye
    CHECK(r[2].is_null());
    CHECK_FALSE(a.contains("cull"));
}

TEST_CASE("vectors v2: cull words per the contract, far plane only when finite") {
    const json boxes = json::array({{{"min", {-0.5, -0.5, -5}}, {"max", {0.5, 0.5, -4}}},
                                    {{"min", {-0.5, -0.5, 1}}, {"max", {0.5, 0.5, 2}}},
                                    {{"min", {-0.5, -0.5, -11}}, {"max", {0.5, 0.5, -9}}},
                                    {{"min", {-0.5, -0.5, -12}}, {"max", {0.5, 0.5, -11}}}});
    CHECK(answer(square_case(nullptr, boxes))["cull"] == json::array({"inside", "outside", "intersect", "outside"}));
    json infinite = square_case(nullptr, boxes);
    infinite["camera"]["perspective"]["far"] = nullptr;
    CHECK(answer(infinite)["cull"] == json::array({"inside", "outside", "inside", "inside"}));
    CHECK_FALSE(answer(square_case(nullptr, boxes)).contains("screen_rects"));
}

TEST_CASE("vectors v2: impossible cases are ok: false with the library's sentence") {
    CHECK(case_error(camera_case("zero_to_one", json::array({{{"jitter", {{"dx", 0.5}, {"dy", 0.5}, {"full_width", 0}, {"full_height", 720}}}}}))) ==
          "ops[0].jitter: frustum::jitter(): offsets must be finite and image sizes finite and > 0, got dx_px=0.5 "
          "dy_px=0.5 width_px=0 height_px=720");
    CHECK(case_error(camera_case("zero_to_one",
                                 json::array({{{"portal", {{"entry", frame({0, 1, 0}, {-1, 0, 0}, {0, 1, 0})},
                                                           {"exit", frame({10, 1, -3}, {0, 0, -1}, {0, 1, 0})}}}}}))) ==
          "ops[0].portal: frustum::portal(): the eye must be on the entry portal's front (positive) side, got "
          "entry_plane=(0, 0, -1, 0) eye_distance=-5");
    CHECK(case_error(camera_case("zero_to_one",
                                 json::array({{{"portal", {{"entry", frame({0, 1, 0}, {0, 0, -1}, {0, 1, 0})},
                                                           {"exit", frame({10, 1, -3}, {0, 0, -1}, {0, 1, 0})}}}}}))) ==
          "ops[0].portal: frustum::portal(): the eye must not lie in the entry portal's plane, got "
          "entry_plane=(1, 0, 0, 0) eye_distance=0");
    CHECK(case_error(camera_case("zero_to_one",
                                 json::array({{{"portal", {{"entry", frame({0, 1, 0}, {2, 0, 0}, {0, 1, 0})},
                                                           {"exit", frame({10, 1, -3}, {0, 0, -1}, {0, 1, 0})}}}}}))) ==
          "ops[0].portal: frustum::portal(): entry frame axes x and y must be unit length and orthogonal (each "
          "within 1e-6), got |x|=2 |y|=1 x.y=0");
    CHECK(case_error(square_case(json::array({{{"corners", {{0, 0, -2}, {1, 0, -2}, {1, 1, -2}}}, {"full_width", 0}, {"full_height", 100}}}), nullptr)) ==
          "rects[0]: frustum::screen_rect(): image sizes must be finite and > 0, got width_px=0 height_px=100");
    CHECK(case_error(square_case(nullptr, json::array({{{"min", {1, 0, -2}}, {"max", {0, 1, -1}}}}))) ==
          "boxes[0]: min must not exceed max, got min=(1, 0, -2) max=(0, 1, -1)");
}

TEST_CASE("vectors v2: malformed version 2 keys are exit 2 and name the place") {
    const auto one = [](const json& c) { return json{{"cases", json::array({c})}}.dump(); };
    CHECK(rejected(one(camera_case("zero_to_one", json::array({{{"jitter", {{"dx", 0.5}, {"dy", 0.5}, {"full_width", 10}}}}}))))
              .find("cases[0].ops[0].jitter.full_height: missing required key") != std::string::npos);
    CHECK(rejected(one(camera_case("zero_to_one", json::array({{{"jitter", {{"dx", "a"}, {"dy", 0.5}, {"full_width", 10}, {"full_height", 10}}}}}))))
              .find("cases[0].ops[0].jitter.dx: expected a number, got string") != std::string::npos);
    CHECK(rejected(one(camera_case("zero_to_one", json::array({{{"portal", {{"entry", frame({0, 0, 0}, {1, 0, 0}, {0, 1, 0})}}}}}))))
              .find("cases[0].ops[0].portal.exit: missing required key") != std::string::npos);
    CHECK(rejected(one(camera_case("zero_to_one", json::array({{{"portal", {{"entry", {{"origin", {0, 0, 0}}, {"x", {1, 0, 0}}, {"y", {0, 1, 0}}, {"z", {0, 0, 1}}}}, {"exit", frame({0, 0, 0}, {1, 0, 0}, {0, 1, 0})}}}}}))))
              .find("cases[0].ops[0].portal.entry.z: unknown key") != std::string::npos);
    CHECK(rejected(one(square_case(json::array({{{"corners", {{0, 0, -2}, {1, 0, -2}}}, {"full_width", 10}, {"full_height", 10}}}), nullptr)))
              .find("cases[0].rects[0].corners: expected an array of 3 or more points, got 2 elements") != std::string::npos);
    CHECK(rejected(one(square_case(nullptr, json::array({{{"min", {0, 0}}, {"max", {1, 1, 1}}}}))))
              .find("cases[0].boxes[0].min: expected an array of 3 numbers, got 2 elements") != std::string::npos);
    CHECK(rejected(one(square_case(nullptr, json{{"min", {0, 0, 0}}})))
              .find("cases[0].boxes: expected an array, got object") != std::string::npos);
}

} // TEST_SUITE
