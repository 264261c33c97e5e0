// The options that replace a derived default, rendered: frustum-demo render
// on a scene written here (a camera at the origin looking down -z, small
// unlit red squares at chosen points), and the squares found in the PNG.
// Where each square must appear is computed here from the camera (GLM's
// perspective, the glTF camera's own numbers) and from what the option
// says, never from the code under test:
//   --lens-center, --lens-radius, --lens-power: eq. 34 inverted by hand, so
//     a square seen at distance d' from the lens centre C in the plain
//     frame appears at d = R (d'/R)^(1/p) (the pixel at distance d shows
//     what the plain camera sees at R (d/R)^p);
//   --slit, --pivot: eq. 36's horizontal coordinate for two vertical planes
//     through the slit line and the camera's side planes at the pivot depth,
//     written out for this camera;
//   --mirror-rect, --mirror-plane: the squares reflected in the plane by
//     hand, projected; the mirror's own pixels inside the rectangle's
//     projection.
#if defined(FRUSTUM_DEMO_EXE)
#include "support.hpp"

#include <doctest/doctest.h>

#include <image/image.hpp>
#include <image/png.hpp>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kW = 320, kH = 180;
constexpr float kYfov = 0.8f, kZnear = 0.1f, kZfar = 100.0f;
constexpr float kAspect = float(kW) / float(kH);
// The sky (render::kClearColor 0.62, 0.74, 0.86 as 8-bit sRGB values, as the PNG holds them).
constexpr int kSkyG = 189;

// A square facing the camera (in a plane z = const), centre and half side.
struct Square {
    glm::vec3 centre;
    float half_m;
};

// The camera's projection, as the glTF camera defines it (GLM, not the app).
glm::mat4 projection() { return glm::perspective(kYfov, kAspect, kZnear, kZfar); }

// Pixel position (x right, y down from the top edge, pixel centres at +0.5)
// of a camera-space point in front of the camera.
glm::dvec2 project(const glm::vec3& p) {
    const glm::dvec4 clip = glm::dmat4(projection()) * glm::dvec4(glm::dvec3(p), 1.0);
    REQUIRE(clip.w > 0.0);
    return {(clip.x / clip.w + 1.0) / 2.0 * kW, (1.0 - clip.y / clip.w) / 2.0 * kH};
}

// The point at depth `depth_m` (in front of the eye) seen at pixel `px`.
glm::vec3 unproject(const glm::dvec2& px, float depth_m) {
    const double tan_v = std::tan(kYfov / 2.0), tan_h = tan_v * kAspect;
    return {float((px.x / kW * 2.0 - 1.0) * tan_h * depth_m), float((1.0 - px.y / kH * 2.0) * tan_v * depth_m),
            -depth_m};
}

// A glTF file with the camera "main" at the origin (looking down -z) and
// the squares, unlit red, double-sided, in one mesh; positions in a .bin beside it.
void write_scene(const std::filesystem::path& dir, const std::vector<Square>& squares) {
    std::vector<float> positions;
    std::vector<std::uint16_t> indices;
    for (const Square& s : squares) {
        const auto base = static_cast<std::uint16_t>(positions.size() / 3);
        for (const auto& [dx, dy] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
            positions.insert(positions.end(), {s.centre.x + dx * s.half_m, s.centre.y + dy * s.half_m, s.centre.z});
        }
        for (int i : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<std::uint16_t>(base + i));
    }
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (std::size_t i = 0; i < positions.size(); i += 3) {
        const glm::vec3 p(positions[i], positions[i + 1], positions[i + 2]);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    std::string bin(positions.size() * 4 + indices.size() * 2, '\0');
    std::memcpy(bin.data(), positions.data(), positions.size() * 4);
    std::memcpy(bin.data() + positions.size() * 4, indices.data(), indices.size() * 2);
    while (bin.size() % 4 != 0) bin.push_back('\0');
    support::write_file(dir / "scene.bin", bin);
    std::ostringstream gltf;
    gltf.precision(9);
    gltf << R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_unlit"], "scene": 0,
"scenes": [{"nodes": [0, 1]}],
"nodes": [{"name": "main", "camera": 0}, {"name": "squares", "mesh": 0}],
"cameras": [{"type": "perspective", "perspective": {"yfov": )"
         << kYfov << R"(, "znear": )" << kZnear << R"(, "zfar": )" << kZfar << R"(, "aspectRatio": )" << kAspect
         << R"(}}],
"materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0, "roughnessFactor": 1},
  "doubleSided": true, "extensions": {"KHR_materials_unlit": {}}}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
"buffers": [{"uri": "scene.bin", "byteLength": )"
         << bin.size() << R"(}],
"bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )"
         << positions.size() * 4 << R"(, "target": 34962},
  {"buffer": 0, "byteOffset": )"
         << positions.size() * 4 << R"(, "byteLength": )" << indices.size() * 2 << R"(, "target": 34963}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": )"
         << positions.size() / 3 << R"(, "type": "VEC3", "min": [)" << lo.x << ", " << lo.y << ", " << lo.z
         << "], \"max\": [" << hi.x << ", " << hi.y << ", " << hi.z << R"(]},
  {"bufferView": 1, "componentType": 5123, "count": )"
         << indices.size() << R"(, "type": "SCALAR"}]}
)";
    support::write_file(dir / "scene.gltf", gltf.str());
}

// frustum-demo render --effect `effect` of the scene in `dir` at kW x kH,
// plus `more`; the PNG read back.
image::Image render(const std::filesystem::path& dir, const std::string& effect, std::vector<std::string> more) {
    const std::string out = (dir / ("out-" + effect)).string();
    std::vector<std::string> args{"render", "--scene", (dir / "scene.gltf").string(), "--effect", effect,
                                  "--size", std::to_string(kW) + "x" + std::to_string(kH), "--out", out};
    args.insert(args.end(), more.begin(), more.end());
    const support::Outcome outcome = rob::run_checked(FRUSTUM_DEMO_EXE, args, 0, false);
    REQUIRE(outcome.exit_status == 0);
    auto picture = image::read_png(out + "/" + effect + ".png");
    REQUIRE_MESSAGE(picture.ok(), picture.error());
    REQUIRE(picture->width == kW);
    REQUIRE(picture->height == kH);
    return std::move(*picture);
}

// How red a pixel is: 0 for the sky (or the sky tinted by the mirror), 1
// for the squares' red, from the green channel (the sky's 189, red's 0;
// anti-aliased edges in between).
double redness(const image::Rgba& p) {
    if (p[0] < 100) return 0.0; // not a red square's pixel, nor its edge over the sky
    return std::clamp((kSkyG - p[1]) / double(kSkyG), 0.0, 1.0);
}

// The red squares of a picture: centroids (weighted by redness) of the
// 8-connected groups of pixels redder than 0.1.
std::vector<glm::dvec2> red_blobs(const image::Image& picture) {
    std::vector<int> group(std::size_t(kW * kH), -1);
    std::vector<glm::dvec2> centroids;
    for (int y0 = 0; y0 < kH; ++y0) {
        for (int x0 = 0; x0 < kW; ++x0) {
            if (group[std::size_t(y0 * kW + x0)] >= 0 || redness(image::pixel_at(picture, x0, y0)) <= 0.1) continue;
            const int id = int(centroids.size());
            glm::dvec2 sum(0.0);
            double weight = 0.0;
            std::vector<std::pair<int, int>> todo{{x0, y0}};
            group[std::size_t(y0 * kW + x0)] = id;
            while (!todo.empty()) {
                const auto [x, y] = todo.back();
                todo.pop_back();
                const double w = redness(image::pixel_at(picture, x, y));
                sum += w * glm::dvec2(x + 0.5, y + 0.5);
                weight += w;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= kW || ny >= kH || group[std::size_t(ny * kW + nx)] >= 0) continue;
                        if (redness(image::pixel_at(picture, nx, ny)) <= 0.1) continue;
                        group[std::size_t(ny * kW + nx)] = id;
                        todo.push_back({nx, ny});
                    }
                }
            }
            centroids.push_back(sum / weight);
        }
    }
    return centroids;
}

// For each expected position, the distance to the nearest blob; each blob
// used once (a missing square shows as a large distance).
std::vector<double> match(const std::vector<glm::dvec2>& expected, std::vector<glm::dvec2> blobs) {
    std::vector<double> distances;
    for (const glm::dvec2& e : expected) {
        auto nearest = std::min_element(blobs.begin(), blobs.end(), [&e](const glm::dvec2& a, const glm::dvec2& b) {
            return glm::distance(a, e) < glm::distance(b, e);
        });
        if (nearest == blobs.end()) {
            distances.push_back(1e9);
            continue;
        }
        distances.push_back(glm::distance(*nearest, e));
        blobs.erase(nearest);
    }
    return distances;
}

double largest(const std::vector<double>& values) { return *std::max_element(values.begin(), values.end()); }

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("render --effect lens --lens-center --lens-radius --lens-power: squares where eq. 34 puts them, magnified near the centre by its factor") {
    if (rob::no_gl()) return;
    support::TempDir dir;
    // The lens the options give, in pixels: centre x, y in [-1, 1] of the
    // frame (1,1 its top right corner), radius a fraction of the half height.
    const double cx = 0.3, cy = -0.2, radius = 0.8;
    const glm::dvec2 centre_px((cx + 1.0) / 2.0 * kW, (1.0 - cy) / 2.0 * kH); // (208, 108)
    const double r_px = radius * kH / 2.0;                                      // 72
    // Three rings of 8 squares about the lens centre, at plain-frame
    // distances R/9, R/4 and 0.64 R, 5 m in front of the eye, each 2 px wide
    // in the plain frame; and one square near the top left corner, so that
    // the model's centre as seen (the derived default) is not the lens centre.
    const float depth_m = 5.0f;
    const float half_m = float(std::tan(kYfov / 2.0) * depth_m * 2.0 / kH); // 1 px
    const std::vector<double> rings = {r_px / 9.0, r_px / 4.0, 0.64 * r_px};
    std::vector<Square> squares;
    std::vector<glm::dvec2> seen; // where the plain frame shows them
    for (std::size_t ring = 0; ring < rings.size(); ++ring) {
        for (int k = 0; k < 8; ++k) {
            const double angle = (k + 0.5 * double(ring)) * 2.0 * M_PI / 8.0;
            seen.push_back(centre_px + rings[ring] * glm::dvec2(std::cos(angle), std::sin(angle)));
        }
    }
    seen.push_back({20.0, 15.0});
    std::vector<glm::dvec2> plain_expected;
    for (const glm::dvec2& px : seen) {
        squares.push_back({unproject(px, depth_m), half_m});
        plain_expected.push_back(project(squares.back().centre));
    }
    write_scene(dir.path(), squares);

    // The plain frame: the squares where GLM's projection puts them (so the
    // camera built here is the one frustum-demo draws with). Bound 0.35 px;
    // measured 0.23 px (the corner square; MSAA edges weighed by their green).
    const std::vector<double> plain = match(plain_expected, red_blobs(render(dir.path(), "plain", {})));
    MESSAGE("plain: largest distance from the projected centre " << largest(plain) << " px");
    CHECK(largest(plain) < 0.35);

    for (const double power : {2.0, 1.5}) {
        CAPTURE(power);
        std::ostringstream power_text;
        power_text << power;
        const image::Image lens = render(dir.path(), "lens",
                                         {"--lens-center", "0.3,-0.2", "--lens-radius", "0.8", "--lens-power",
                                          power_text.str(), "--lens-grid", "32"});
        // eq. 34 inverted: a square the plain frame shows at distance d'
        // from C appears at d = R (d'/R)^(1/p), on the same ray from C.
        std::vector<glm::dvec2> expected;
        for (const glm::dvec2& px : seen) {
            const double d = glm::distance(px, centre_px);
            expected.push_back(centre_px + r_px * std::pow(d / r_px, 1.0 / power) * (px - centre_px) / d);
        }
        const std::vector<glm::dvec2> blobs = red_blobs(lens);
        CHECK(blobs.size() == squares.size());
        const std::vector<double> moved = match(expected, blobs);
        MESSAGE("lens p = " << power << ": largest distance from eq. 34's position " << largest(moved) << " px");
        // Each tile maps its four moved corners projectively, eq. 34 only at
        // the corners (tiles of 10 x 5.6 px here). Bound 0.75 px; measured
        // 0.40 px (p = 2), 0.32 px (p = 1.5).
        CHECK(largest(moved) < 0.75);
        // The lens as measured (each blob the one nearest its expected
        // position): the centre as the mean of a ring's 8 squares, the
        // radius from the outer ring (d' = 0.64 R; on the inner ones the
        // inversion multiplies a position's error by p / (p - 1) / (d / R)),
        // d = R (d'/R)^(1/p) giving R = (d^p / d')^(1/(p - 1)).
        const auto found = [&](std::size_t i) {
            const glm::dvec2 e = expected[i];
            return *std::min_element(blobs.begin(), blobs.end(), [&e](const glm::dvec2& a, const glm::dvec2& b) {
                return glm::distance(a, e) < glm::distance(b, e);
            });
        };
        for (std::size_t ring = 0; ring < rings.size(); ++ring) {
            CAPTURE(ring);
            glm::dvec2 centre(0.0);
            double radius_px = 0.0;
            for (std::size_t k = 0; k < 8; ++k) {
                centre += found(ring * 8 + k) / 8.0;
                const double d = glm::distance(found(ring * 8 + k), centre_px);
                radius_px += std::pow(std::pow(d, power) / rings[ring], 1.0 / (power - 1.0)) / 8.0;
            }
            MESSAGE("ring " << ring << ": centre (" << centre.x << ", " << centre.y << "), radius " << radius_px
                            << " px; --lens-center and --lens-radius say (" << centre_px.x << ", " << centre_px.y
                            << "), " << r_px);
            // Bounds 0.25 px and 0.3 px; measured at most 0.07 px off
            // centre, the outer ring's radius 0.02 px (p = 2) and 0.04 px
            // (p = 1.5) off. The derived defaults (the squares' centre as
            // seen, half their radius as seen within 0.1..0.4 of the half
            // height) are tens of pixels away.
            CHECK(glm::distance(centre, centre_px) < 0.25);
            if (ring == 2) CHECK(std::abs(radius_px - r_px) < 0.3);
            // The magnification near the lens centre (paper §5.4): eq. 34
            // sends the pixel at distance d from C to the plain frame's
            // d' = R (d/R)^p, so what lies at d' appears scaled by
            // d / d' = (R / d')^(1 - 1/p) about C, without bound as d' -> 0
            // for p > 1. Measured on the two inner rings (d' = R/9, R/4,
            // the plain frame's squares checked above at their GLM
            // projection) as their mean distance from their own measured
            // centre over d', against that factor computed here from R and p
            // (p = 2: 3 and 2; p = 1.5: 2.080 and 1.587). (Over the plain
            // frame's measured ring instead of d' it is no better: a 2 px
            // square's centroid moves in steps of the 4 MSAA samples, up to
            // 0.17 px, 1% of d'.)
            if (ring < 2) {
                double mean_d = 0.0;
                for (std::size_t k = 0; k < 8; ++k) mean_d += glm::distance(found(ring * 8 + k), centre) / 8.0;
                const double measured = mean_d / rings[ring];
                const double eq34 = std::pow(r_px / rings[ring], 1.0 - 1.0 / power);
                MESSAGE("ring " << ring << " (d' = " << rings[ring] << " px): magnified " << measured
                                << " x, eq. 34: " << eq34 << " x");
                // Bound 1.5%; measured -0.70% and -0.21% (p = 2: 2.979 for
                // 3, 1.996 for 2), -0.85% and -0.24% (p = 1.5: 2.062 for
                // 2.080, 1.584 for 1.587). A power 5% low (1.9 for 2) gives
                // 2.83 for 3.
                CHECK(std::abs(measured / eq34 - 1.0) < 0.015);
            }
        }
    }
}

TEST_CASE("render --effect nonaffine --slit --pivot: squares where eq. 36's crossed slits put them") {
    if (rob::no_gl()) return;
    support::TempDir dir;
    // The slit frustum for this camera, by hand: the left plane turned
    // about the vertical line of the camera's left plane at the pivot depth
    // P until it contains the slit line (x = 0 at depth S), the right plane
    // alike; top and bottom the camera's. The two planes are mirror images,
    // so d_l / (d_l + d_r) is the fraction of the way from the left plane
    // to the right one at the point's depth z, where they stand at
    // -+ P tan_h (z - S) / (P - S): u = 1/2 + x (P - S) / (2 P tan_h (z - S)).
    // Vertical: the camera's own perspective.
    const double slit = 2.0, pivot = 5.0; // the defaults would be 7.5 and 2.5 (the model's centre at 7.5 m)
    const double tan_v = std::tan(kYfov / 2.0), tan_h = tan_v * kAspect;
    struct Placed {
        double x, y, depth;
    };
    // Each about 3 px wide in the plain frame; at 3 m (between slit and
    // pivot, stretched sideways), 5 m (the pivot: as plain), 9 and 12 m (beyond: squeezed).
    const std::vector<Placed> placed = {{-0.8, 0.3, 3.0}, {0.6, -0.25, 3.0}, {-1.5, -0.5, 5.0}, {1.2, 0.6, 5.0},
                                        {-4.0, 1.0, 9.0}, {3.0, -1.2, 9.0},  {2.0, 2.0, 12.0}, {-5.0, -2.0, 12.0}};
    std::vector<Square> squares;
    std::vector<glm::dvec2> plain_expected, slit_expected;
    for (const Placed& p : placed) {
        const float half_m = float(1.5 * 2.0 * tan_v * p.depth / kH);
        squares.push_back({glm::vec3(float(p.x), float(p.y), float(-p.depth)), half_m});
        plain_expected.push_back(project(squares.back().centre));
        const double u = 0.5 + p.x * (pivot - slit) / (2.0 * pivot * tan_h * (p.depth - slit));
        slit_expected.push_back({u * kW, plain_expected.back().y});
    }
    write_scene(dir.path(), squares);
    // Bound 0.35 px as in the lens case; measured 0.15 px.
    const std::vector<double> plain = match(plain_expected, red_blobs(render(dir.path(), "plain", {})));
    MESSAGE("plain: largest distance from the projected centre " << largest(plain) << " px");
    CHECK(largest(plain) < 0.35);
    // How far the squares move from the plain frame: 0 at the pivot depth.
    std::vector<double> shift;
    for (std::size_t i = 0; i < placed.size(); ++i) shift.push_back(glm::distance(plain_expected[i], slit_expected[i]));
    MESSAGE("eq. 36 moves the squares off the pivot depth by up to " << largest(shift) << " px");

    const image::Image nonaffine = render(dir.path(), "nonaffine", {"--slit", "2", "--pivot", "5"});
    const std::vector<glm::dvec2> blobs = red_blobs(nonaffine);
    CHECK(blobs.size() == squares.size());
    const std::vector<double> moved = match(slit_expected, blobs);
    MESSAGE("nonaffine: largest distance from eq. 36's position " << largest(moved) << " px");
    // Bound 0.25 px; measured 0.12 px (the squares stay rectangles: u is
    // affine in x and v in y at each depth; the triangles subdivided at 0.25 m).
    CHECK(largest(moved) < 0.25);
}

TEST_CASE("render --effect mirror --mirror-rect and --mirror-plane: the scene reflected in the given plane") {
    if (rob::no_gl()) return;
    support::TempDir dir;
    // Three squares 3 m in front of the eye; the mirror 6 m in front, facing
    // the eye (z = -6, reflecting towards +z): each square's reflection is
    // the square at z = -9.
    const double tan_v = std::tan(kYfov / 2.0);
    const std::vector<glm::vec3> centres = {{0.6f, 0.15f, -3.0f}, {-1.2f, -0.7f, -3.0f}, {1.2f, 0.7f, -3.0f}};
    std::vector<Square> squares;
    std::vector<glm::dvec2> expected;
    const glm::vec4 plane(0.0f, 0.0f, 1.0f, 6.0f); // a x + b y + c z + d = 0
    for (const glm::vec3& c : centres) {
        squares.push_back({c, float(1.5 * 2.0 * tan_v * 3.0 / kH)});
        expected.push_back(project(c));
        const glm::vec3 n(plane);
        const glm::vec3 reflected = c - 2.0f * (glm::dot(n, c) + plane.w) / glm::dot(n, n) * n;
        expected.push_back(project(reflected));
    }
    write_scene(dir.path(), squares);

    // --mirror-rect: centre (0, 0, -6), sides (3, 0, 0) and (0, 2, 0) (a x b = +z, towards the eye).
    // Every square and its reflection where GLM projects them.
    const auto check_squares = [&expected](const image::Image& frame, const std::string& option) {
        const std::vector<glm::dvec2> blobs = red_blobs(frame);
        CHECK(blobs.size() == expected.size());
        const std::vector<double> found = match(expected, blobs);
        MESSAGE(option << ": largest distance from the projected squares and reflections " << largest(found) << " px");
        CHECK(largest(found) < 0.25); // measured 0.15 px with either option
    };
    const image::Image rect = render(dir.path(), "mirror", {"--mirror-rect", "0,0,-6,3,0,0,0,2,0"});
    {
        check_squares(rect, "--mirror-rect");
        // The mirror's own pixels (the sky reflected, tinted: not the sky,
        // not red) inside the rectangle's projection, corners c +- a/2 +- b/2.
        glm::dvec2 lo(1e9), hi(-1e9);
        for (const auto& [sa, sb] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
            const glm::dvec2 corner = project(glm::vec3(0.0f, 0.0f, -6.0f) + sa * glm::vec3(1.5f, 0, 0) +
                                              sb * glm::vec3(0, 1.0f, 0));
            lo = glm::min(lo, corner);
            hi = glm::max(hi, corner);
        }
        int outside = 0, missing = 0, mirror_pixels = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                const image::Rgba p = image::pixel_at(rect, x, y);
                const bool sky = std::abs(p[0] - 158) <= 2 && std::abs(p[1] - kSkyG) <= 2 && std::abs(p[2] - 219) <= 2;
                const bool red = redness(p) > 0.1;
                const glm::dvec2 c(x + 0.5, y + 0.5);
                // (The projection is an axis-aligned rectangle here: the mirror faces the eye squarely.)
                const bool inside = c.x > lo.x + 1.0 && c.x < hi.x - 1.0 && c.y > lo.y + 1.0 && c.y < hi.y - 1.0;
                const bool near = c.x > lo.x - 1.0 && c.x < hi.x + 1.0 && c.y > lo.y - 1.0 && c.y < hi.y + 1.0;
                mirror_pixels += !sky && !red;
                outside += !sky && !red && !near;
                missing += sky && inside;
            }
        }
        // Measured: 7758 mirror pixels, 0 outside, 0 missing.
        MESSAGE("--mirror-rect: " << mirror_pixels << " mirror pixels, " << outside
                                  << " outside the projected rectangle (1 px margin), " << missing
                                  << " sky pixels more than 1 px inside it; rectangle x " << lo.x << ".." << hi.x
                                  << ", y " << lo.y << ".." << hi.y);
        CHECK(mirror_pixels > 0);
        CHECK(outside == 0);
        CHECK(missing == 0);
    }
    // --mirror-plane: the same plane (a square about the foot of the model's centre).
    check_squares(render(dir.path(), "mirror", {"--mirror-plane", "0,0,1,6"}), "--mirror-plane");
}

} // TEST_SUITE
#endif
