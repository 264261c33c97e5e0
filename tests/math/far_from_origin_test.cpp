// World-space cameras far from the origin: a scene placed at (5000, 120,
// -2000) m, the eye 1.4 m above a floor mirror. The eye tests of mirror,
// clip_oblique, portal and culling_pair compare c . M^-1_2 (the plane's
// side of the eye) with its own rounding bound, term by term
// (detail::eye_side_floor): |c| |M^-1_2| would grow with the distance from
// the origin squared and refuse these planes as "passing through the eye".
// lens_tiles builds its tiles relative to the eye (in world coordinates
// from_planes refused them as degenerate).
#include "support.hpp"

using namespace mtest;
using frustum::Frame;

namespace {

const glm::dvec3 far_eye(5000.0, 121.4, -2000.0);
const glm::dvec3 far_target(5003.0, 120.3, -2004.0);

template <class T>
MatrixPair<T> far_camera(DepthRange depth) {
    const auto p = frustum::perspective<T>(T(pi / 3), T(16.0 / 9.0), T(0.1), T(200), depth);
    const auto v = frustum::look_at<T>(Vec3<T>(far_eye), Vec3<T>(far_target), Vec3<T>(0, 1, 0));
    REQUIRE(p.ok());
    REQUIRE(v.ok());
    return frustum::compose(*p, *v);
}

// The floor mirror y = 120, facing up (the eye is 1.4 m above it).
template <class T>
Plane<T> floor_plane() {
    return Plane<T>(0, 1, 0, -120);
}

// Lengths here are good to a few ulp of the coordinates (5000 m): 5e-4 m in
// float.
template <class T>
double length_tolerance_m() {
    return 64 * eps<T>() * 5400.0;
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("mirror and clip_oblique work 5 km from the origin", T, float, double) {
    for (DepthRange depth : all_depth_ranges) {
        CAPTURE(depth);
        const MatrixPair<T> camera = far_camera<T>(depth);
        const auto mirrored = frustum::mirror(camera, floor_plane<T>());
        REQUIRE_MESSAGE(mirrored.ok(), mirrored.error());
        CHECK(inverse_residual(*mirrored) <= 64 * eps<T>());
        // The mirror camera's eye is the real eye reflected in the floor.
        const auto eye = frustum::eye_point(*mirrored);
        REQUIRE(eye.has_value());
        CHECK(glm::distance(glm::dvec3(*eye), glm::dvec3(5000.0, 118.6, -2000.0)) < length_tolerance_m<T>());
        // Its near plane is the mirror: a point of the floor in view is on it.
        const auto near = frustum::planes(*mirrored).near;
        CHECK(std::abs(double(near.distance(Vec3<T>(5003, 120, -2004)))) < length_tolerance_m<T>());

        // The same plane facing down: the eye on its negative side, as
        // clip_oblique asks; its near plane is then the floor too.
        const auto clipped = frustum::clip_oblique(camera, floor_plane<T>().flipped());
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        CHECK(inverse_residual(*clipped) <= 64 * eps<T>());
        CHECK(std::abs(double(frustum::planes(*clipped).near.distance(Vec3<T>(5003, 120, -2004)))) <
              length_tolerance_m<T>());

        const auto culling = frustum::culling_pair(camera, floor_plane<T>(), frustum::CropRect<T>{0, 0, 1, 1, 1, 1});
        CHECK_MESSAGE(culling.ok(), culling.error());
    }
}

TEST_CASE_TEMPLATE("portal works 5 km from the origin", T, float, double) {
    const MatrixPair<T> camera = far_camera<T>(DepthRange::ZeroToOne);
    // Entry 3 m ahead facing the eye, exit 10 m to the side.
    const Frame<T> entry{Vec3<T>(5002, 121, -2003), Vec3<T>(0.8, 0, 0.6), Vec3<T>(0, 1, 0)};
    const Frame<T> exit{Vec3<T>(5010, 121, -2006), Vec3<T>(0, 0, -1), Vec3<T>(0, 1, 0)};
    const auto through = frustum::portal(camera, entry, exit);
    REQUIRE_MESSAGE(through.ok(), through.error());
    // (normwise: the oblique frames leave entries of M M^-1 that are a single
    // rounded product of two non-zero terms, 100% off entrywise at 1e-29)
    CHECK(inverse_residual_normwise(*through) <= 64 * eps<T>());
    // The virtual eye: the real one, (0.2, 0.4, 3.6) in the entry's frame,
    // carried to (-0.2, 0.4, -3.6) in the exit's.
    const auto eye = frustum::eye_point(*through);
    REQUIRE(eye.has_value());
    CHECK(glm::distance(glm::dvec3(*eye), glm::dvec3(5006.4, 121.4, -2005.8)) < length_tolerance_m<T>());
    const auto culling = frustum::culling_pair(camera, entry, exit, frustum::CropRect<T>{0, 0, 1, 1, 1, 1});
    CHECK_MESSAGE(culling.ok(), culling.error());
}

TEST_CASE_TEMPLATE("5 km from the origin a plane through the eye is still refused", T, float, double) {
    const MatrixPair<T> camera = far_camera<T>(DepthRange::ZeroToOne);
    const auto eye = frustum::eye_point(camera);
    REQUIRE(eye.has_value());
    // The horizontal plane through the eye as the pair holds it.
    const Plane<T> through(0, 1, 0, -eye->y);
    const auto mirrored = frustum::mirror(camera, through);
    REQUIRE_FALSE(mirrored.ok());
    CHECK(mirrored.error().find("mirror plane must not pass through the eye") != std::string::npos);
    const auto clipped = frustum::clip_oblique(camera, through);
    REQUIRE_FALSE(clipped.ok());
    CHECK(clipped.error().find("clip plane must not pass through the eye") != std::string::npos);
    const auto culling = frustum::culling_pair(camera, through, frustum::CropRect<T>{0, 0, 1, 1, 1, 1});
    REQUIRE_FALSE(culling.ok());
    CHECK(culling.error().find("mirror plane must not pass through the eye") != std::string::npos);
}

TEST_CASE_TEMPLATE("lens_tiles 5 km from the origin: the tiles at the origin, moved", T, float, double) {
    const MatrixPair<T> camera = far_camera<T>(DepthRange::ZeroToOne);
    const auto p = frustum::perspective<T>(T(pi / 3), T(16.0 / 9.0), T(0.1), T(200), DepthRange::ZeroToOne);
    const auto v = frustum::look_at<T>(Vec3<T>(0, 0, 0), Vec3<T>(far_target - far_eye), Vec3<T>(0, 1, 0));
    REQUIRE(p.ok());
    REQUIRE(v.ok());
    const MatrixPair<T> at_origin = frustum::compose(*p, *v);
    const auto frame = frustum::near_plane_frame(camera);
    REQUIRE(frame.ok());
    const frustum::Lens<T> lens{frustum::Vec2<T>(T(0)), T(0.6) * frame->half_height_m, T(2)};
    const auto far_tiles = frustum::lens_tiles(camera, lens, 320, 180, 4, 3);
    REQUIRE_MESSAGE(far_tiles.ok(), far_tiles.error());
    const auto origin_tiles = frustum::lens_tiles(at_origin, lens, 320, 180, 4, 3);
    REQUIRE(origin_tiles.ok());
    REQUIRE(far_tiles->size() == origin_tiles->size());
    for (std::size_t i = 0; i < far_tiles->size(); ++i) {
        CAPTURE(i);
        const auto far_k = frustum::key_points((*far_tiles)[i].pair);
        const auto origin_k = frustum::key_points((*origin_tiles)[i].pair);
        for (int c = 0; c < 4; ++c) { // the near corners, 0.1 m from the eye
            const glm::dvec3 far_corner(frustum::to_point(far_k.corners[c], T(1e-6)));
            const glm::dvec3 origin_corner(frustum::to_point(origin_k.corners[c], T(1e-6)));
            CHECK(glm::distance(far_corner - far_eye, origin_corner) < length_tolerance_m<T>());
        }
    }
}

} // TEST_SUITE
