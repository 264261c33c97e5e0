// classify() on boxes and spheres, and culling_pair() for mirror and portal
// passes (culling.hpp, NOTES.md erratum 8).
#include "support.hpp"

using namespace mtest;
using frustum::Aabb;
using frustum::Containment;
using frustum::CropRect;
using frustum::Sphere;

namespace {

// 90 degrees, square, near 1, far 10, at the origin looking down -z.
template <class T>
MatrixPair<T> square_camera() {
    const auto p = frustum::perspective<T>(T(pi / 2), T(1), T(1), T(10), DepthRange::ZeroToOne);
    REQUIRE(p.ok());
    return *p;
}

// Camera at (0, 2, 6) looking at the origin over a floor mirror y = 0.
template <class T>
MatrixPair<T> floor_camera(std::optional<T> far_m = T(20)) {
    const auto p = frustum::perspective<T>(T(pi / 3), T(1), T(0.1), far_m, DepthRange::ZeroToOne);
    const auto v = frustum::look_at<T>(Vec3<T>(0, 2, 6), Vec3<T>(0, 0, 0), Vec3<T>(0, 1, 0));
    REQUIRE(p.ok());
    REQUIRE(v.ok());
    return frustum::compose(*p, *v);
}

template <class T>
std::vector<Vec3<T>> floor_quad() {
    return {{-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}};
}

template <class T>
Aabb<T> cube(const Vec3<T>& centre, T half) {
    return {centre - Vec3<T>(half), centre + Vec3<T>(half)};
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("classify: boxes and spheres inside, outside and across, each plane", T, float, double) {
    const auto planes = frustum::planes(square_camera<T>());
    CHECK(frustum::classify(planes, Aabb<T>{{-0.5, -0.5, -5}, {0.5, 0.5, -4}}) == Containment::Inside);
    CHECK(frustum::classify(planes, Aabb<T>{{-0.5, -0.5, 1}, {0.5, 0.5, 2}}) == Containment::Outside);   // behind
    CHECK(frustum::classify(planes, Aabb<T>{{-0.5, -0.5, -12}, {0.5, 0.5, -11}}) == Containment::Outside); // far
    CHECK(frustum::classify(planes, Aabb<T>{{6, -0.5, -5}, {7, 0.5, -4}}) == Containment::Outside);     // right
    CHECK(frustum::classify(planes, Aabb<T>{{-0.5, -0.5, -11}, {0.5, 0.5, -9}}) == Containment::Intersecting);
    CHECK(frustum::classify(planes, Aabb<T>{{-0.5, -0.5, -1.5}, {0.5, 0.5, -0.5}}) == Containment::Intersecting);
    CHECK(frustum::classify(planes, Sphere<T>{{0, 0, -5}, 1}) == Containment::Inside);
    CHECK(frustum::classify(planes, Sphere<T>{{0, 0, -5}, 4}) == Containment::Intersecting);
    CHECK(frustum::classify(planes, Sphere<T>{{0, 0, 2}, 1}) == Containment::Outside);
    CHECK(frustum::classify(planes, Sphere<T>{{0, 0, -12}, 2.5}) == Containment::Intersecting); // 2 beyond far
    CHECK(frustum::classify(planes, Sphere<T>{{0, 0, -12}, 1.5}) == Containment::Outside);
}

TEST_CASE_TEMPLATE("classify: the conservative false \"intersecting\" near a frustum edge (pinned)", T, float,
                   double) {
    // Near the edge where the left plane (x >= z) meets the far plane
    // (z >= -10), at (-10, y, -10). The box x in [-12, -10.5], z in
    // [-11, -9.5] pokes past the left plane (its corner (-10.5, -11) has
    // x - z = 0.5 > 0) and past the far plane (z = -9.5 > -10), so neither
    // plane has all eight corners behind it; yet no point of the box is in
    // the frustum (x >= z and z >= -10 would need x >= -10 > -10.5).
    const auto planes = frustum::planes(square_camera<T>());
    const Aabb<T> box{{-12, -0.5, -11}, {-10.5, 0.5, -9.5}};
    CHECK(frustum::classify(planes, box) == Containment::Intersecting); // conservative: really outside
    Random rng(7301);
    for (int i = 0; i < 20000; ++i) { // ... which sampling confirms
        const Vec3<T> p(T(rng.uniform(-12, -10.5)), T(rng.uniform(-0.5, 0.5)), T(rng.uniform(-11, -9.5)));
        const Vec4<T> c = square_camera<T>().matrix() * Vec4<T>(p, T(1));
        REQUIRE_FALSE(clip_inside(c, DepthRange::ZeroToOne));
    }
}

TEST_CASE_TEMPLATE("classify: never Outside for a box that holds a point of the frustum", T, float, double) {
    for_each_random_camera<T>(7302, 500, [&](Random& rng, const CameraSpec& spec, const MatrixPair<T>& pair) {
        const auto planes = frustum::planes(pair);
        const glm::dvec4 h = glm::dmat4(pair.inverse()) * random_clip_point(rng, spec.depth, 0.01);
        const glm::dvec3 p = glm::dvec3(h) / h.w;
        const glm::dvec3 lo = p - glm::dvec3(rng.uniform(0, 5), rng.uniform(0, 5), rng.uniform(0, 5));
        const glm::dvec3 hi = p + glm::dvec3(rng.uniform(0, 5), rng.uniform(0, 5), rng.uniform(0, 5));
        INFO("camera: ", spec.text());
        CHECK(frustum::classify(planes, Aabb<T>{Vec3<T>(lo), Vec3<T>(hi)}) != Containment::Outside);
    });
}

TEST_CASE_TEMPLATE("culling_pair (mirror): near = mirror plane, far = the camera's own far distance", T, float,
                   double) {
    const MatrixPair<T> camera = floor_camera<T>();
    const Plane<T> floor(0, 1, 0, 0);
    const auto rect = frustum::screen_rect(camera, floor_quad<T>(), T(100), T(100));
    REQUIRE_MESSAGE(rect.ok(), rect.error());
    REQUIRE(rect->has_value());
    const auto mirrored = frustum::mirror(camera, floor);
    REQUIRE(mirrored.ok());
    const auto render = frustum::crop(*mirrored, **rect); // what the pass draws with
    const auto cull = frustum::culling_pair(camera, floor, **rect);
    REQUIRE_MESSAGE(render.ok(), render.error());
    REQUIRE_MESSAGE(cull.ok(), cull.error());
    CHECK(cull->planes.near.abcd == Vec4<T>(0, 1, 0, 0));
    CHECK(cull->pair.flips_winding());
    CHECK(inverse_residual(cull->pair) <= 256 * eps<T>());
    // The far plane is 20 from the reflected eye (0, -2, 6).
    REQUIRE(cull->planes.far.has_value());
    const Vec3<T> reflected_eye(0, -2, 6);
    CHECK(std::abs(double(cull->planes.far->distance(reflected_eye)) - 20) <= loose<T>() * 100);
    // ... perpendicular to the reflected view direction (0, 2, -6), facing the eye.
    CHECK(cull->planes.far->normal() == close_abs(Vec3<T>(glm::normalize(glm::dvec3(0, -2, 6))), loose<T>() * 10));

    const auto render_planes = frustum::planes(*render);
    // Behind the mirror, inside the reflected (unclipped) frustum: the
    // unclipped pair keeps it, the culling pair (and the render) drop it.
    const Vec3<T> axis = glm::normalize(Vec3<T>(0, 0, 0) - reflected_eye);
    const Aabb<T> under = cube<T>(reflected_eye + axis * T(1.5), T(0.2)); // y = -1.53
    CHECK(frustum::classify(frustum::planes(cull->pair), under) != Containment::Outside);
    CHECK(frustum::classify(cull->planes, under) == Containment::Outside);
    CHECK(frustum::classify(render_planes, under) == Containment::Outside);
    // Beyond the camera's far distance along the reflected view axis, but in
    // front of the oblique frustum's tilted far plane: the render frustum
    // keeps it (it would be drawn: the tilt goes through only one far
    // corner and lies beyond the far distance everywhere else), the culling
    // pair drops it as the camera's far plane says.
    const Aabb<T> beyond = cube<T>(reflected_eye + axis * T(23), T(0.2));
    CHECK(frustum::classify(render_planes, beyond) != Containment::Outside);
    CHECK(frustum::classify(cull->planes, beyond) == Containment::Outside);
    const Aabb<T> seen = cube<T>(reflected_eye + axis * T(12), T(0.2));
    CHECK(frustum::classify(cull->planes, seen) == Containment::Inside);
    CHECK(frustum::classify(render_planes, seen) == Containment::Inside);
}

TEST_CASE_TEMPLATE("culling_pair (mirror): the culling frustum is the render frustum cut at the far distance", T,
                   float, double) {
    // The oblique clip never cuts into the camera's far distance: every
    // point of the render frustum that the culling far plane keeps is inside
    // the culling frustum, and every point of the culling frustum is inside
    // the render frustum. So no box the camera should see is culled, and
    // (unlike the tilted far plane) nothing beyond the far distance is kept.
    Random rng(7303);
    const MatrixPair<T> camera = floor_camera<T>();
    const Plane<T> floor(0, 1, 0, 0);
    const auto rect = frustum::screen_rect(camera, floor_quad<T>(), T(100), T(100));
    REQUIRE(rect.ok());
    REQUIRE(rect->has_value());
    const auto render = frustum::crop(*frustum::mirror(camera, floor), **rect);
    const auto cull = frustum::culling_pair(camera, floor, **rect);
    REQUIRE(render.ok());
    REQUIRE(cull.ok());
    const auto render_planes = frustum::planes(*render);
    const auto inside = [](const frustum::FrustumPlanes<T>& planes, const glm::dvec3& p, double tolerance) {
        for (const auto& plane : planes.as_array()) {
            if (plane && double(plane->distance(Vec3<T>(p))) < -tolerance) return false;
        }
        return true;
    };
    const double tolerance = sizeof(T) == 4 ? 1e-3 : 1e-9;
    int beyond_far = 0, kept = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec4 h = glm::dmat4(render->inverse()) * random_clip_point(rng, DepthRange::ZeroToOne, 0.001);
        if (!(h.w > 0)) continue; // the part of the clip box beyond infinity (behind the eye)
        const glm::dvec3 p = glm::dvec3(h) / h.w;
        if (double(cull->planes.far->distance(Vec3<T>(p))) < -tolerance) {
            ++beyond_far; // the tilted far plane reaches past the far distance here
            continue;
        }
        ++kept;
        CHECK(inside(cull->planes, p, tolerance));
    }
    CHECK(beyond_far > 100);
    CHECK(kept > 100);
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec4 h = glm::dmat4(cull->pair.inverse()) * random_clip_point(rng, DepthRange::ZeroToOne, 0.001);
        if (!(h.w > 0)) continue;
        const glm::dvec3 p = glm::dvec3(h) / h.w;
        if (!inside(cull->planes, p, -tolerance)) continue; // behind the mirror
        CHECK(inside(render_planes, p, tolerance));
    }
}

TEST_CASE_TEMPLATE("culling_pair (portal): near = exit plane, far at the camera's distance from the virtual eye", T,
                   float, double) {
    const MatrixPair<T> camera = floor_camera<T>();
    // Entry: the floor quad seen from above (front +y); exit: a wall x = 10
    // facing +x. n = x × y: entry x = (1, 0, 0), y = (0, 0, -1) -> n = (0, 1, 0).
    const frustum::Frame<T> entry{{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
    const frustum::Frame<T> exit{{10, 1, 0}, {0, 0, -1}, {0, 1, 0}};
    const auto rect = frustum::screen_rect(camera, floor_quad<T>(), T(100), T(100));
    REQUIRE(rect.ok());
    REQUIRE(rect->has_value());
    const auto cull = frustum::culling_pair(camera, entry, exit, **rect);
    REQUIRE_MESSAGE(cull.ok(), cull.error());
    CHECK(cull->planes.near.abcd == close_abs(Vec4<T>(1, 0, 0, -10), loose<T>()));
    CHECK_FALSE(cull->pair.flips_winding());
    const auto carry = frustum::portal_transform(entry, exit);
    REQUIRE(carry.ok());
    const Vec3<T> virtual_eye(carry->inverse * Vec4<T>(0, 2, 6, 1));
    REQUIRE(cull->planes.far.has_value());
    CHECK(std::abs(double(cull->planes.far->distance(virtual_eye)) - 20) <= loose<T>() * 100);
    // Infinite far: no far plane to cull with.
    const auto open = frustum::culling_pair(floor_camera<T>(std::nullopt), entry, exit, **rect);
    REQUIRE(open.ok());
    CHECK_FALSE(open->planes.far.has_value());
}

// `text` is `prefix` followed by a number within `tolerance` of `value`.
static void check_text_then_number(const std::string& text, const std::string& prefix, double value, double tolerance) {
    INFO(text);
    REQUIRE(text.rfind(prefix, 0) == 0);
    const std::string number = text.substr(prefix.size());
    std::size_t used = 0;
    const double read = std::stod(number, &used);
    CHECK(used == number.size());
    CHECK(std::abs(read - value) <= tolerance);
}

TEST_CASE_TEMPLATE("culling_pair: errors, exact texts", T, float, double) {
    const MatrixPair<T> camera = floor_camera<T>();
    const CropRect<T> rect{0, 0, 50, 50, 100, 100};
    // The eye distance is read back from the inverse: -2 and 0 to within a
    // few ulps (exactly in double on x86-64; FMA contraction on aarch64
    // moves the last bits), so the number is read, not compared as text.
    const double ulps = 8 * double(eps<T>()) * 2;
    check_text_then_number(frustum::culling_pair(camera, Plane<T>(0, -1, 0, 0), rect).error(),
                           "frustum::culling_pair(): the eye must be on the mirror plane's positive (front) side, "
                           "got plane=(0, -1, 0, 0) eye_distance=", -2, ulps);
    check_text_then_number(frustum::culling_pair(camera, Plane<T>(0, 1, 0, -2), rect).error(),
                           "frustum::culling_pair(): mirror plane must not pass through the eye, got "
                           "plane=(0, 1, 0, -2) eye_distance=", 0, ulps);
    CHECK(frustum::culling_pair(camera, Plane<T>(0, 1, 0, 0), CropRect<T>{60, 0, 50, 50, 100, 100}).error() ==
          "frustum::culling_pair(): frustum::crop(): crop rectangle must lie inside the image, got x=60 y=0 "
          "width=50 height=50 full_width=100 full_height=100");
    const frustum::Frame<T> entry{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}; // n = (0, -1, 0): eye behind
    const frustum::Frame<T> exit{{10, 1, 0}, {0, 0, -1}, {0, 1, 0}};
    check_text_then_number(frustum::culling_pair(camera, entry, exit, rect).error(),
                           "frustum::culling_pair(): the eye must be on the entry portal's front (positive) side, "
                           "got entry_plane=(0, -1, 0, 0) eye_distance=", -2, ulps);
    CHECK(frustum::culling_pair(camera, entry, frustum::Frame<T>{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, rect)
              .error()
              .rfind("frustum::culling_pair(): exit frame axes x and y must be unit length", 0) == 0);
}

} // TEST_SUITE
