#include "vectors/camera.hpp"

#include <frustum/from_planes.hpp>
#include <frustum/mirror.hpp>
#include <frustum/plane.hpp>
#include <frustum/projection.hpp>

#include <type_traits>

namespace vectors {

namespace {

using Pair = frustum::MatrixPair<double>;
using PairResult = frustum::Result<Pair>;

constexpr double kPi = 3.14159265358979323846;

struct Maker {
    frustum::DepthRange depth;

    PairResult operator()(const PerspectiveCamera& c) const {
        // Degrees only at the JSON boundary; the library takes radians.
        const double fovy_rad = c.fovy_deg * (kPi / 180.0);
        return frustum::perspective(fovy_rad, c.aspect, c.near_m, c.far_m, depth);
    }
    PairResult operator()(const FrustumCamera& c) const {
        return frustum::off_axis(c.left, c.right, c.bottom, c.top, c.near_m, c.far_m, depth);
    }
    PairResult operator()(const OrthoCamera& c) const {
        return frustum::orthographic(c.left, c.right, c.bottom, c.top, c.near_m, c.far_m, depth);
    }
    PairResult operator()(const PlanesCamera& c) const {
        const frustum::SidePlanes<double> planes{frustum::Plane<double>(c.left), frustum::Plane<double>(c.right),
                                                 frustum::Plane<double>(c.bottom), frustum::Plane<double>(c.top),
                                                 frustum::Plane<double>(c.near)};
        if (c.far_point) {
            return frustum::from_planes(planes, *c.far_point, depth); // §4.1
        }
        auto grown = frustum::from_planes_volume_growth(planes, depth); // §4.2, erratum 12
        if (!grown) {
            return grown.take_error();
        }
        return grown->pair;
    }
    PairResult operator()(const MirrorRectCamera& c) const {
        const frustum::Rectangle<double> rectangle{c.corner, c.a1, c.a2};
        return frustum::mirror_rectangle(rectangle, c.eye, c.far_m, c.fit, depth);
    }
    PairResult operator()(const MatrixCamera& c) const { return frustum::from_matrix(c.matrix, depth); }
};

} // namespace

const char* camera_name(const Camera& camera) {
    return std::visit(
        [](const auto& c) -> const char* {
            using C = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<C, PerspectiveCamera>) return "perspective";
            if constexpr (std::is_same_v<C, FrustumCamera>) return "frustum";
            if constexpr (std::is_same_v<C, OrthoCamera>) return "ortho";
            if constexpr (std::is_same_v<C, PlanesCamera>) return "planes";
            if constexpr (std::is_same_v<C, MirrorRectCamera>) return "mirror_rect";
            return "matrix";
        },
        camera);
}

frustum::Result<frustum::MatrixPair<double>> make_camera(const Camera& camera, frustum::DepthRange depth) {
    return std::visit(Maker{depth}, camera);
}

} // namespace vectors
