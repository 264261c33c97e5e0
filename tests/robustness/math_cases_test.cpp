// Bad input to the math library: each row names the call and the phrases
// its error must contain. Every error is a Result (nothing asserts, nothing
// throws, nothing divides by zero under -DFRUSTUM_SANITIZE=ON) in the one
// format "frustum::<function>(): <rule>, got <values>". Each call runs in a
// child process, so a crash fails its row and the table goes on.
#include "support.hpp"

#include <doctest/doctest.h>
#include <frustum/frustum.hpp>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace frustum;
using D = double;
constexpr DepthRange kZo = DepthRange::ZeroToOne;
const D kNaN = std::numeric_limits<D>::quiet_NaN();
const D kInf = std::numeric_limits<D>::infinity();

struct MathCase {
    const char* input;
    std::function<std::string()> error; // the call's error text ("" when it succeeded)
    std::vector<std::string> phrases;
};

template <class R>
std::string error_of(const R& result) {
    return result.ok() ? std::string() : result.error();
}

MatrixPair<D> camera() { return *perspective<D>(1.0, 1.0, 1.0, D(10), kZo); }

// The side planes of camera(), eye at the origin looking down -z.
SidePlanes<D> side_planes() {
    const FrustumPlanes<D> p = raw_planes(camera());
    return {p.left, p.right, p.bottom, p.top, p.near};
}

const std::vector<MathCase>& math_cases() {
    static const std::vector<MathCase> cases = {
        {"perspective near -1", [] { return error_of(perspective<D>(1, 1, -1, D(10), kZo)); },
         {"frustum::perspective(): near must be > 0", "near=-1"}},
        {"perspective near 0, infinite far", [] { return error_of(perspective<D>(1, 1, 0, infinite_far, kZo)); },
         {"frustum::perspective(): near must be > 0", "near=0"}},
        {"perspective far == near", [] { return error_of(perspective<D>(1, 1, 2, D(2), kZo)); },
         {"far must be finite and > near", "near=2 far=2"}},
        {"perspective far < near", [] { return error_of(perspective<D>(1, 1, 2, D(1), kZo)); },
         {"far must be finite and > near", "far=1"}},
        {"perspective fovy NaN", [] { return error_of(perspective<D>(kNaN, 1, 1, D(10), kZo)); },
         {"frustum::perspective(): fovy_rad must be in (0, pi)", "nan"}},
        {"perspective fovy pi", [] { return error_of(perspective<D>(3.14159265358979323846, 1, 1, D(10), kZo)); },
         {"fovy_rad must be in (0, pi)"}},
        {"perspective aspect 0", [] { return error_of(perspective<D>(1, 0, 1, D(10), kZo)); },
         {"frustum::perspective(): aspect must be > 0 and finite, got aspect=0"}},
        {"perspective aspect infinite", [] { return error_of(perspective<D>(1, kInf, 1, D(10), kZo)); },
         {"aspect must be > 0 and finite", "aspect=inf"}},
        {"off_axis left == right", [] { return error_of(off_axis<D>(1, 1, -1, 1, 1, D(10), kZo)); },
         {"frustum::off_axis(): need left < right and bottom < top"}},
        {"orthographic near == far", [] { return error_of(orthographic<D>(-1, 1, -1, 1, 5, 5, kZo)); },
         {"frustum::orthographic(): need left < right, bottom < top and near < far", "near=5 far=5"}},
        {"look_at eye == target", [] { return error_of(look_at<D>({1, 2, 3}, {1, 2, 3}, {0, 1, 0})); },
         {"frustum::look_at(): eye must differ from target"}},
        {"look_at up parallel", [] { return error_of(look_at<D>({0, 0, 0}, {0, 5, 0}, {0, 1, 0})); },
         {"up must be non-zero and not parallel to the viewing direction"}},
        {"look_at up zero", [] { return error_of(look_at<D>({0, 0, 0}, {0, 0, -1}, {0, 0, 0})); },
         {"up must be non-zero"}},
        {"from_matrix zero (singular)", [] { return error_of(from_matrix(Mat4<D>(0), kZo)); },
         {"frustum::from_matrix(): matrix is singular or too ill-conditioned to invert"}},
        {"from_matrix rank 3", [] {
             Mat4<D> m(1);
             set_row(m, 3, row(m, 0) + row(m, 1));
             return error_of(from_matrix(m, kZo));
         }, {"singular or too ill-conditioned"}},
        {"from_matrix with NaN", [] {
             Mat4<D> m(1);
             m[2][1] = kNaN;
             return error_of(from_matrix(m, kZo));
         }, {"frustum::from_matrix(): every entry must be finite"}},
        {"from_planes non-concurrent", [] {
             SidePlanes<D> p = side_planes();
             p.left.abcd.w += 0.5 * glm::length(p.left.normal());
             return error_of(from_planes(p, Vec3<D>(0, 0, -5), kZo));
         }, {"frustum::from_planes(): side planes do not meet in one point"}},
        {"from_planes zero-normal plane", [] {
             SidePlanes<D> p = side_planes();
             p.top = Plane<D>(0, 0, 0, 1);
             return error_of(from_planes(p, Vec3<D>(0, 0, -5), kZo));
         }, {"top plane must be finite with a non-zero normal", "(0, 0, 0, 1)"}},
        {"from_planes far point behind the eye", [] {
             return error_of(from_planes(side_planes(), Vec3<D>(0, 0, 5), kZo));
         }, {"far point must be in front of the eye and beyond the near plane"}},
        {"from_planes far point on the near plane up to rounding", [] {
             const SidePlanes<D> p = side_planes();
             const D length = glm::length(p.near.normal());
             const Vec3<D> normal = p.near.normal() / length;
             const Vec3<D> on_near = -(p.near.abcd.w / length) * normal;
             return error_of(from_planes(p, on_near + 1e-12 * glm::length(on_near) * normal, kZo));
         }, {"frustum::from_planes(): far point must lie clearly beyond the near plane"}},
        {"from_planes far point NaN", [] {
             return error_of(from_planes(side_planes(), Vec3<D>(kNaN, 0, -5), kZo));
         }, {"frustum::from_planes(): far point must be finite"}},
        {"volume growth, near plane facing the eye", [] {
             SidePlanes<D> p = side_planes();
             p.near = p.near.flipped();
             return error_of(from_planes_volume_growth(p, kZo));
         }, {"frustum::from_planes_volume_growth()", "the eye must be on the near plane's negative side"}},
        {"crop outside the image", [] { return error_of(crop(camera(), CropRect<D>{500, 0, 400, 300, 800, 600})); },
         {"frustum::crop(): crop rectangle must lie inside the image", "x=500"}},
        {"crop of zero width", [] { return error_of(crop(camera(), CropRect<D>{0, 0, 0, 10, 800, 600})); },
         {"frustum::crop(): crop and image sizes must be > 0"}},
        {"crop with infinity", [] { return error_of(crop(camera(), CropRect<D>{0, 0, kInf, 10, 800, 600})); },
         {"crop rectangle must be finite"}},
        {"crop_tiles more columns than pixels", [] { return error_of(crop_tiles(camera(), 4, 4, 5, 1)); },
         {"frustum::crop_tiles(): need 1 <= columns <= width_px"}},
        {"reflect zero-normal plane", [] { return error_of(reflect(camera(), Plane<D>(0, 0, 0, 1))); },
         {"frustum::reflect(): plane normal must be non-zero and finite"}},
        {"clip plane through the eye", [] { return error_of(clip_oblique(camera(), Plane<D>(0, 1, 0, 0))); },
         {"frustum::clip_oblique(): clip plane must not pass through the eye", "plane=(0, 1, 0, 0)"}},
        {"clip with the eye on the positive side", [] {
             return error_of(clip_oblique(camera(), Plane<D>(0, 0, 1, 2))); // eye z = 0: 2 > 0
         }, {"frustum::clip_oblique(): the eye must be on the clip plane's negative side"}},
        {"clip hiding everything", [] { return error_of(clip_oblique(camera(), Plane<D>(0, 0, 1, -2))); },
         {"frustum::clip_oblique(): clip plane leaves no part of the frustum visible"}},
        {"mirror seen from behind", [] { return error_of(mirror(camera(), Plane<D>(0, 0, -1, -3))); },
         {"frustum::mirror(): the eye must be on the mirror plane's positive (front) side"}},
        {"mirror_rectangle with a zero side", [] {
             return error_of(mirror_rectangle<D>({{0, 0, -3}, {0, 0, 0}, {0, 1, 0}}, {0, 0, 0}, 100,
                                                 MirrorFit::Exact, kZo));
         }, {"frustum::mirror_rectangle(): rectangle is degenerate", "a1=(0, 0, 0)"}},
        {"mirror_rectangle far too small", [] {
             return error_of(mirror_rectangle<D>({{-1, -1, -3}, {2, 0, 0}, {0, 2, 0}}, {0, 0, 0}, 0.5,
                                                 MirrorFit::Exact, kZo));
         }, {"frustum::mirror_rectangle(): far must exceed the near distance", "near=3 far=0.5"}},
        {"lens_tiles on an orthographic camera", [] {
             return error_of(lens_tiles(*orthographic<D>(-1, 1, -1, 1, 1, 10, kZo), Lens<D>{}, 64, 64, 2, 2));
         }, {"frustum::lens_tiles():", "needs a perspective camera"}},
        {"lens_tiles with radius 0", [] {
             Lens<D> lens;
             lens.radius_m = 0;
             return error_of(lens_tiles(camera(), lens, 64, 64, 2, 2));
         }, {"frustum::lens_tiles(): lens needs a finite centre, radius > 0 and power > 0", "radius=0"}},
        {"non-affine frustum with the inside point outside", [] {
             const Plane<D> l(-1, 0, 0, -1), r(1, 0, 0, -1), b(0, -1, 0, -1), t(0, 1, 0, -1), n(0, 0, 1, 1),
                 f(0, 0, -1, -10);
             return error_of(NonAffineFrustum<D>::from_planes(l, r, b, t, n, f, Vec3<D>(5, 0, -5), kZo));
         }, {"frustum::NonAffineFrustum::from_planes(): the inside point must be on the negative (inner) side",
             "right plane"}},
        // An all-zero target: X0..X3 coincide, no side plane exists.
        {"fit_volume with a degenerate target", [] { return error_of(fit_volume(VolumeTarget<D>{}, D(10), kZo)); },
         {"frustum::fit_volume(): near points and side normals must be finite, normals non-zero"}},
    };
    return cases;
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("math: every bad input is an error naming the broken rule") {
    support::for_each_case(math_cases(), 30, [](const MathCase& c) {
        const rob::Isolated call = rob::isolated(c.error); // a crash fails this row only
        CHECK_MESSAGE(call.finished, "the call did not return: ", call.how);
        if (!call.finished) return;
        CHECK_FALSE(call.value.empty());
        support::check_message(call.value, "frustum::", c.phrases, true);
    });
}

} // TEST_SUITE
