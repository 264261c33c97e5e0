// frustum-vectors error paths: malformed requests (exit 2, nothing on
// stdout, the place named on stderr) and well-formed but geometrically
// impossible cases (ok: false with a sentence; the other cases answered).
#include <cmath>
#include "vectors_support.hpp"

#include <string>
#include <utility>
#include <vector>

using namespace vectors_test;

namespace {

const std::string kGoodCamera = R"({"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": 0.1, "far": 100}})";
const std::string kView = R"("view": {"eye": [0, 1, 5], "target": [0, 0, 0], "up": [0, 1, 0]})";
const std::string kSide = R"("left": [1, 0, -1, 0], "right": [-1, 0, -1, 0], "bottom": [0, 1, -1, 0], "top": [0, -1, -1, 0])";

std::string one(const std::string& case_body) { return R"({"cases": [{"id": "x", )" + case_body + "}]}"; }
std::string with_camera(const std::string& camera) { return one(R"("camera": )" + camera); }
std::string with_ops(const std::string& ops) { return one(R"("camera": )" + kGoodCamera + ", " + kView + R"(, "ops": )" + ops); }

} // namespace

TEST_SUITE("cli") {

TEST_CASE("vectors: malformed JSON is exit 2 with the line and column") {
    const std::pair<const char*, const char*> cases[] = {
        {"", "invalid JSON at line 1, column 1: the input is empty"},
        {"  \n ", "invalid JSON at line 2, column 2: the input is empty"},
        {"{", "invalid JSON at line 1, column 2: expected a key string"},
        {"{\"cases\": [}", "invalid JSON at line 1, column 12: unexpected character, expected a value"},
        {"{\"cases\": [1,]}", "invalid JSON at line 1, column 14: unexpected character, expected a value"},
        {"{\"cases\": []} x", "invalid JSON at line 1, column 15: unexpected text after the document"},
        {"{\"cases\":\n [NaN]}", "invalid JSON at line 2, column 3: unexpected character, expected a value"},
        {"{\"cases\": [Infinity]}", "invalid JSON at line 1, column 12: unexpected character, expected a value"},
        {"{\"cases\": [01]}", "invalid JSON at line 1, column 13: a number must not have leading zeros"},
        {"{\"cases\": [1.]}", "invalid JSON at line 1, column 14: expected a digit after '.'"},
        {"{\"cases\": [-]}", "invalid JSON at line 1, column 13: expected a digit"},
        {"{'cases': []}", "invalid JSON at line 1, column 2: expected a key string"},
        {"// c\n{}", "invalid JSON at line 1, column 1: unexpected character, expected a value"},
        {"\xEF\xBB\xBF{}", "invalid JSON at line 1, column 1: unexpected character, expected a value"},
        {"{\"a\": \"\xC3\"}", "invalid JSON at line 1, column 8: invalid UTF-8 in string"},
        {"{\"a\": \"\xED\xA0\x80\"}", "invalid JSON at line 1, column 8: invalid UTF-8 in string"},
        {"{\"a\": \"\\ud800\"}", "invalid JSON at line 1, column 14: unpaired high surrogate in \\u escape"},
        {"{\"a\": \"tab\there\"}", "invalid JSON at line 1, column 11: control character in string (escape it)"},
        {"{\"a\": \"\\x\"}", "invalid JSON at line 1, column 9: invalid escape sequence"},
        {"{\"a\": tru}", "invalid JSON at line 1, column 7: unexpected character"},
        {"{\"a\": 1, \"a\": 2}", "invalid JSON at line 1, column 10: duplicate key \"a\""},
        {"{\"a\": \"unterminated}", "invalid JSON at line 1, column 21: unterminated string"},
    };
    for (const auto& c : cases) {
        // Named references, not a structured binding: INFO captures its
        // argument in a lambda, which may not capture bindings before C++20.
        const auto& text = c.first;
        INFO("input: " << text);
        CHECK(rejected(text) == std::string("frustum-vectors: ") + c.second + "\n");
    }
    const std::string deep = std::string(65, '[') + std::string(65, ']');
    CHECK(rejected(deep).find("nest deeper than 64 levels") != std::string::npos);
    const std::string ok_depth = "{\"cases\": [], \"x\": " + std::string(60, '[') + std::string(60, ']') + "}";
    CHECK(rejected(ok_depth) == "frustum-vectors: x: unknown key (expected one of cases)\n"); // parsed, then refused
}

TEST_CASE("vectors: request shape errors are exit 2 and name the place") {
    const std::pair<std::string, const char*> cases[] = {
        // document
        {"[]", "(document): expected an object, got array"},
        {"{}", "cases: missing required key"},
        {R"({"cases": {}})", "cases: expected an array, got object"},
        {R"({"cases": [], "version": 1})", "version: unknown key (expected one of cases)"},
        {R"({"cases": [7]})", "cases[0]: expected an object, got number"},
        // case
        {R"({"cases": [{"camera": {}}]})", "cases[0].id: missing required key"},
        {R"({"cases": [{"id": 3}]})", "cases[0].id: expected a string, got number"},
        {R"({"cases": [{"id": "x"}]})", "cases[0].camera: missing required key"},
        {one(R"("camera": )" + kGoodCamera + R"(, "colour": "red")"),
         "cases[0].colour: unknown key (expected one of id, depth, camera, view, ops, points, rects, boxes)"},
        {one(R"("depth": "", "camera": )" + kGoodCamera),
         "cases[0].depth: unknown depth range \"\" (expected zero_to_one, minus_one_to_one or reversed_zero_to_one)"},
        {one(R"("depth": "zero_to_two", "camera": )" + kGoodCamera),
         "cases[0].depth: unknown depth range \"zero_to_two\" (expected zero_to_one, minus_one_to_one or reversed_zero_to_one)"},
        {one(R"("depth": 1, "camera": )" + kGoodCamera), "cases[0].depth: expected a string, got number"},
        // camera
        {with_camera("{}"), "cases[0].camera: expected exactly one of perspective, frustum, ortho, planes, mirror_rect, matrix, got none"},
        {with_camera(R"({"perspective": {"fovy_deg": 60, "aspect": 1, "near": 1, "far": 2}, "ortho": {}})"),
         "cases[0].camera: expected exactly one of perspective, frustum, ortho, planes, mirror_rect, matrix, got 2: ortho, perspective"},
        {with_camera(R"({"fisheye": {}})"),
         "cases[0].camera.fisheye: unknown key (expected one of perspective, frustum, ortho, planes, mirror_rect, matrix)"},
        {with_camera("[]"), "cases[0].camera: expected an object, got array"},
        {with_camera(R"({"perspective": {"fovy_deg": "60", "aspect": 1.5, "near": 0.1, "far": 100}})"),
         "cases[0].camera.perspective.fovy_deg: expected a number, got string"},
        {with_camera(R"({"perspective": {"fovy_deg": "NaN", "aspect": 1.5, "near": 0.1, "far": 100}})"),
         "cases[0].camera.perspective.fovy_deg: expected a number, got string"},
        {with_camera(R"({"perspective": {"fovy_deg": 60, "aspect": true, "near": 0.1, "far": 100}})"),
         "cases[0].camera.perspective.aspect: expected a number, got boolean"},
        {with_camera(R"({"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": 0.1}})"),
         "cases[0].camera.perspective.far: missing required key"},
        {with_camera(R"({"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": 0.1, "far": "Infinity"}})"),
         "cases[0].camera.perspective.far: expected a number or null, got string"},
        {with_camera(R"({"perspective": {"fov": 60, "aspect": 1.5, "near": 0.1, "far": 100}})"),
         "cases[0].camera.perspective.fov: unknown key (expected one of fovy_deg, aspect, near, far)"},
        {with_camera(R"({"frustum": {"left": -1, "right": 1, "bottom": -1, "top": 1, "far": 10}})"),
         "cases[0].camera.frustum.near: missing required key"},
        {with_camera(R"({"ortho": {"left": -1, "right": 1, "bottom": -1, "top": 1, "near": 0, "far": null}})"),
         "cases[0].camera.ortho.far: expected a number, got null"},
        {with_camera(R"({"planes": {)" + kSide + R"(, "near": [0, 0, -1]}})"),
         "cases[0].camera.planes.near: expected an array of 4 numbers, got 3 elements"},
        {with_camera(R"({"planes": {)" + kSide + R"(, "near": [0, 0, -1, -1]}})"),
         "cases[0].camera.planes: expected exactly one of far_point ([x, y, z]) and far (\"volume\")"},
        {with_camera(R"({"planes": {)" + kSide + R"(, "near": [0, 0, -1, -1], "far": "volume", "far_point": [0, 0, -9]}})"),
         "cases[0].camera.planes: expected exactly one of far_point ([x, y, z]) and far (\"volume\")"},
        {with_camera(R"({"planes": {)" + kSide + R"(, "near": [0, 0, -1, -1], "far": "infinite"}})"),
         "cases[0].camera.planes.far: expected \"volume\" (or give far_point instead)"},
        {with_camera(R"({"planes": {)" + kSide + R"(, "near": [0, 0, -1, -1], "far_point": [0, "0", -9]}})"),
         "cases[0].camera.planes.far_point[1]: expected a number, got string"},
        {with_camera(R"({"mirror_rect": {"corner": [0, 0, 0], "a1": [1, 0, 0], "a2": [0, 1, 0], "eye": [0, 0, 1], "far": 9, "fit": "best"}})"),
         "cases[0].camera.mirror_rect.fit: expected \"paper\" or \"exact\", got \"best\""},
        {with_camera(R"({"mirror_rect": {"corner": [0, 0, 0], "a1": [1, 0, 0], "a2": [0, 1, 0], "eye": [0, 0, 1], "far": 9}})"),
         "cases[0].camera.mirror_rect.fit: missing required key"},
        {with_camera(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0]})"),
         "cases[0].camera.matrix: expected an array of 16 numbers, got 15 elements"},
        {with_camera(R"({"matrix": {"m00": 1}})"), "cases[0].camera.matrix: expected an array of 16 numbers, got object"},
        // view
        {one(R"("camera": )" + kGoodCamera + R"(, "view": {"eye": [0, 1, 5], "target": [0, 0, 0]})"),
         "cases[0].view.up: missing required key"},
        {one(R"("camera": )" + kGoodCamera + R"(, "view": {"eye": [0, 1, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 1})"),
         "cases[0].view.fov: unknown key (expected one of eye, target, up)"},
        {one(R"("camera": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}, )" + kView),
         "cases[0].view: not allowed with camera \"matrix\", which is already in world space"},
        {one(R"("camera": {"planes": {)" + kSide + R"(, "near": [0, 0, -1, -1], "far": "volume"}}, )" + kView),
         "cases[0].view: not allowed with camera \"planes\", which is already in world space"},
        {one(R"("camera": {"mirror_rect": {"corner": [0, 0, 0], "a1": [1, 0, 0], "a2": [0, 1, 0], "eye": [0, 0, 1], "far": 9, "fit": "exact"}}, )" + kView),
         "cases[0].view: not allowed with camera \"mirror_rect\", which is already in world space"},
        // ops
        {with_ops("{}"), "cases[0].ops: expected an array, got object"},
        {with_ops("[[]]"), "cases[0].ops[0]: expected an object, got array"},
        {with_ops(R"([{"rotate": {"angle": 1}}])"), "cases[0].ops[0].rotate: unknown key (expected one of crop, reflect, clip, mirror, jitter, portal)"},
        {with_ops(R"([{"reflect": {"plane": [0, 1, 0, 0]}, "clip": {"plane": [0, 1, 0, 0]}}])"),
         "cases[0].ops[0]: expected exactly one of crop, reflect, clip, mirror, jitter, portal, got 2: clip, reflect"},
        {with_ops(R"([{"crop": {"x": 0, "y": 0, "width": 1, "full_width": 2, "full_height": 2}}])"),
         "cases[0].ops[0].crop.height: missing required key"},
        {with_ops(R"([{"crop": {"x": 0, "y": 0, "w": 1, "width": 1, "height": 1, "full_width": 2, "full_height": 2}}])"),
         "cases[0].ops[0].crop.w: unknown key (expected one of x, y, width, height, full_width, full_height)"},
        {with_ops(R"([{"mirror": {}}])"), "cases[0].ops[0].mirror.plane: missing required key"},
        {with_ops(R"([{"clip": {"plane": [0, 1, 0, 0], "side": 1}}])"), "cases[0].ops[0].clip.side: unknown key (expected one of plane)"},
        {with_ops(R"([{"reflect": {"plane": [0, 1, 0]}}])"), "cases[0].ops[0].reflect.plane: expected an array of 4 numbers, got 3 elements"},
        // points
        {one(R"("camera": )" + kGoodCamera + R"(, "points": [0, 0, 1])"), "cases[0].points[0]: expected an array of 3 numbers, got number"},
        {one(R"("camera": )" + kGoodCamera + R"(, "points": [[0, 0]])"), "cases[0].points[0]: expected an array of 3 numbers, got 2 elements"},
        {one(R"("camera": )" + kGoodCamera + R"(, "points": [[0, null, 0]])"), "cases[0].points[0][1]: expected a number, got null"},
    };
    for (const auto& c : cases) {
        // Named references, not a structured binding: INFO captures its
        // argument in a lambda, which may not capture bindings before C++20.
        const auto& text = c.first;
        INFO("input: " << text);
        CHECK(rejected(text) == std::string("frustum-vectors: ") + c.second + "\n");
    }
}

TEST_CASE("vectors: one malformed case rejects the whole document, even after good ones") {
    const std::string text = R"({"cases": [{"id": "good", "camera": )" + kGoodCamera + R"(},
                                           {"id": "bad", "camera": )" + kGoodCamera + R"(, "oops": 1}]})";
    CHECK(rejected(text) == "frustum-vectors: cases[1].oops: unknown key (expected one of id, depth, camera, view, ops, points, rects, boxes)\n");
}

TEST_CASE("vectors: impossible geometry is ok: false and the other cases are still answered") {
    struct Bad {
        const char* id;
        std::string body; // the case without its id
        std::vector<const char*> words; // must all appear in the error sentence
    };
    const std::string rect = R"("corner": [-1, 0, -2], "a1": [2, 0, 0], "a2": [0, 1.5, 0], "eye": [0.3, 1, 2])";
    const std::string crop = R"({"crop": {"x": %X, "y": 0, "width": %W, "height": 360, "full_width": 1280, "full_height": 720}})";
    const auto crop_op = [&crop](const char* x, const char* w) {
        std::string c = crop;
        c.replace(c.find("%X"), 2, x);
        c.replace(c.find("%W"), 2, w);
        return "[" + c + "]";
    };
    const std::vector<Bad> bad = {
        {"near-negative", R"("camera": {"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": -1, "far": 100}})",
         {"camera.perspective: ", "near must be > 0", "near=-1"}},
        {"near-zero", R"("camera": {"frustum": {"left": -1, "right": 1, "bottom": -1, "top": 1, "near": 0, "far": null}})",
         {"camera.frustum: ", "near must be > 0", "near=0"}},
        {"aspect-zero", R"("camera": {"perspective": {"fovy_deg": 60, "aspect": 0, "near": 0.1, "far": 100}})",
         {"camera.perspective: ", "aspect must be > 0", "aspect=0"}},
        {"fovy-overflow", R"("camera": {"perspective": {"fovy_deg": 1e999, "aspect": 1.5, "near": 0.1, "far": 100}})",
         {"camera.perspective: ", "fovy", "inf"}},
        {"far-overflow", R"("camera": {"perspective": {"fovy_deg": 60, "aspect": 1.5, "near": 0.1, "far": 1e999}})",
         {"camera.perspective: ", "far must be finite", "far=inf"}},
        {"ortho-overflow", R"("camera": {"ortho": {"left": -1e999, "right": 1, "bottom": -1, "top": 1, "near": 0, "far": 1}})",
         {"camera.ortho: ", "finite", "left=-inf"}},
        {"point-overflow", R"("camera": )" + kGoodCamera + R"(, "points": [[0, 0, -1], [0, -1e999, 0]])",
         {"points[1]: ", "finite", "-inf"}},
        {"up-parallel", R"("camera": )" + kGoodCamera + R"(, "view": {"eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, 2, 0]})",
         {"view: ", "look_at", "not parallel"}},
        {"up-zero", R"("camera": )" + kGoodCamera + R"(, "view": {"eye": [0, 1, 5], "target": [0, 0, 0], "up": [0, 0, 0]})",
         {"view: ", "up must be non-zero"}},
        {"eye-is-target", R"("camera": )" + kGoodCamera + R"(, "view": {"eye": [1, 2, 3], "target": [1, 2, 3], "up": [0, 1, 0]})",
         {"view: ", "eye must differ from target"}},
        {"clip-through-eye", R"("camera": )" + kGoodCamera + ", " + kView + R"(, "ops": [{"clip": {"plane": [0, 1, 0, -1]}}])",
         {"ops[0].clip: ", "clip_oblique", "through the eye"}},
        {"clip-eye-on-positive-side", R"("camera": )" + kGoodCamera + ", " + kView + R"(, "ops": [{"clip": {"plane": [0, 1, 0, 0]}}])",
         {"ops[0].clip: ", "negative side"}},
        {"far-point-behind-eye", R"("camera": {"planes": {)" + kSide + R"(, "near": [0, 0, -1, -1], "far_point": [0, 0, 5]}})",
         {"camera.planes: ", "far point must be in front of the eye"}},
        {"far-point-before-near", R"("camera": {"planes": {)" + kSide + R"(, "near": [0, 0, -1, -1], "far_point": [0, 0, -0.5]}})",
         {"camera.planes: ", "beyond the near plane"}},
        {"planes-not-concurrent", R"("camera": {"planes": {"left": [1, 0, -1, 0.5], "right": [-1, 0, -1, 0], "bottom": [0, 1, -1, 0], "top": [0, -1, -1, 0], "near": [0, 0, -1, -1], "far": "volume"}})",
         {"camera.planes: ", "do not meet in one point"}},
        {"matrix-singular", R"("camera": {"matrix": [1, 2, 3, 4, 2, 4, 6, 8, 0, 0, 1, 0, 0, 0, 0, 1]})",
         {"camera.matrix: ", "from_matrix", "singular"}},
        {"crop-outside", R"("camera": )" + kGoodCamera + R"(, "ops": )" + crop_op("700", "640"),
         {"ops[0].crop: ", "inside the image", "x=700"}},
        {"crop-zero-size", R"("camera": )" + kGoodCamera + R"(, "ops": )" + crop_op("0", "0"),
         {"ops[0].crop: ", "must be > 0", "width=0"}},
        {"mirror-rect-degenerate", R"("camera": {"mirror_rect": {"corner": [0, 0, 0], "a1": [1, 0, 0], "a2": [-2, 0, 0], "eye": [0, 1, 1], "far": 9, "fit": "paper"}})",
         {"camera.mirror_rect: ", "degenerate"}},
        {"mirror-rect-zero-side", R"("camera": {"mirror_rect": {"corner": [0, 0, 0], "a1": [1, 0, 0], "a2": [0, 0, 0], "eye": [0, 1, 1], "far": 9, "fit": "exact"}})",
         {"camera.mirror_rect: ", "degenerate"}},
        {"mirror-rect-far-too-small", R"("camera": {"mirror_rect": {)" + rect + R"(, "far": 1, "fit": "exact"}})",
         {"camera.mirror_rect: ", "far must exceed"}},
        {"mirror-from-behind", R"("camera": )" + kGoodCamera + ", " + kView + R"(, "ops": [{"mirror": {"plane": [0, -1, 0, 0]}}])",
         {"ops[0].mirror: ", "mirror"}},
        {"second-op-fails", R"("camera": )" + kGoodCamera + ", " + kView +
                                R"(, "ops": [{"reflect": {"plane": [1, 0, 0, 0]}}, {"crop": {"x": 0, "y": 0, "width": 2, "height": 1, "full_width": 1, "full_height": 1}}])",
         {"ops[1].crop: ", "inside the image"}},
    };
    std::string text = R"({"cases": [{"id": "first-good", "camera": )" + kGoodCamera + "}";
    for (const Bad& b : bad) {
        text += std::string(R"(, {"id": ")") + b.id + R"(", )" + b.body + "}";
        text += R"(, {"id": "good-after-)" + std::string(b.id) + R"(", "camera": )" + kGoodCamera + ", " + kView + "}";
    }
    text += "]}";
    const Run r = run_text(text);
    REQUIRE_MESSAGE(r.status == 0, r.err);
    CHECK(r.err.empty());
    const json response = json::parse(r.out);
    REQUIRE(response["cases"].size() == 1 + 2 * bad.size());
    CHECK(response["cases"][0]["ok"].get<bool>());
    for (std::size_t i = 0; i < bad.size(); ++i) {
        const json& c = response["cases"][1 + 2 * i];
        INFO("case " << bad[i].id);
        CHECK(c["id"] == bad[i].id);
        REQUIRE_FALSE(c["ok"].get<bool>());
        CHECK(c.size() == 3);
        const std::string error = c["error"].get<std::string>();
        INFO("error: " << error);
        CHECK(error.rfind(bad[i].words[0], 0) == 0); // starts with the place
        for (const char* word : bad[i].words) {
            CHECK(error.find(word) != std::string::npos);
        }
        const json& good = response["cases"][2 + 2 * i];
        CHECK(good["id"] == "good-after-" + std::string(bad[i].id));
        CHECK(good["ok"].get<bool>());
        CHECK(good.contains("matrix"));
    }
}

TEST_CASE("vectors: a mirror seen from behind says so") {
    const std::string error =
        case_error(json::parse(R"({"id": "m", "camera": )" + kGoodCamera + ", " + kView +
                               R"(, "ops": [{"mirror": {"plane": [0, -1, 0, 0]}}]})"));
    CHECK(error.rfind("ops[0].mirror: frustum::mirror(): ", 0) == 0);
    // Either the mirror's own wording or the clip's: the eye is on the wrong side.
    CHECK((error.find("side") != std::string::npos));
}

TEST_CASE("vectors: results too large for a double are ok: false, never NaN or inf in the output") {
    // The inverse of this frustum would have an entry (r - l) / 2n = 1e310:
    // the library refuses it (and, with near = 1e-300, the underflow of
    // 2n / (r - l) to 0 as well).
    CHECK(case_error(json::parse(R"({"id": "huge", "camera": {"frustum": {"left": -1e300, "right": 1e300, "bottom": -1,
        "top": 1, "near": 1e-10, "far": 1e300}}})")) ==
          "camera.frustum: frustum::off_axis(): frustum too thin or too deep to represent, got near=1e-10 far=1e+300");
    CHECK(case_error(json::parse(R"({"id": "tiny", "camera": {"frustum": {"left": -1e300, "right": 1e300, "bottom": -1,
        "top": 1, "near": 1e-300, "far": 1e300}}})"))
              .find("too thin or too deep") != std::string::npos);
    // Corners at +-1e200: |xyz| would overflow if computed naively, but the
    // canonical form scales first, so the answer is representable. With
    // |w| <= 1e-12 |xyz| (frustum::infinity_tolerance<double>) such a corner
    // is a point at infinity: w = 0 and a unit direction.
    {
        const json wide = answer(json::parse(R"({"id": "wide", "camera": {"ortho": {"left": -1e200, "right": 1e200,
            "bottom": -1e200, "top": 1e200, "near": 0, "far": 1e200}}})"));
        REQUIRE(wide["ok"].get<bool>());
        // A unit direction normalized in double: a few ulps from sqrt(1/2).
        CHECK(wide["corners"][0][0].get<double>() == doctest::Approx(std::sqrt(0.5)).epsilon(1e-15));
        CHECK(wide["corners"][0][1].get<double>() == doctest::Approx(std::sqrt(0.5)).epsilon(1e-15));
        CHECK(wide["corners"][0][3].get<double>() == 0.0);
    }
    // A plane at infinity (row 3 = (-1, 0, 0, 1) makes m3 + m0 = (0, 0, 0, 1)).
    CHECK(case_error(json::parse(R"({"id": "left-at-infinity", "camera": {"matrix": [1, 0, 0, -1, 0, 1, 0, 0, 0, 0, 1, 0,
        0, 0, 0, 1]}})")) == "planes: the left plane has a zero or non-finite normal (a plane at infinity)");
    // A point whose clip coordinates overflow.
    CHECK(case_error(json::parse(R"({"id": "far-point", "camera": )" + kGoodCamera +
                                 R"(, "points": [[1.7e308, 0, -1e308]]})")) ==
          "result: clip is not representable in double (the frustum is too large or too thin)");
}

} // TEST_SUITE
