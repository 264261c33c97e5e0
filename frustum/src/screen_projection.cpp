#include "frustum/screen_projection.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/finite.hpp"
#include "frustum/detail/tolerances.hpp"
#include "frustum/detail/window_camera.hpp"

#include <cmath>

namespace frustum {

template <class T>
Result<MatrixPair<T>> screen_projection(const Vec3<T>& pa, const Vec3<T>& pb, const Vec3<T>& pc, const Vec3<T>& pe,
                                        T near_m, std::optional<T> far_m, DepthRange depth) {
    if (!detail::finite3(pa) || !detail::finite3(pb) || !detail::finite3(pc) || !detail::finite3(pe)) {
        return detail::error_text("screen_projection", "corners and eye must be finite",
                                  "lower_left=" + detail::vector_text(pa) + " lower_right=" + detail::vector_text(pb) +
                                      " upper_left=" + detail::vector_text(pc) + " eye=" + detail::vector_text(pe));
    }
    const Vec3<T> right_edge = pb - pa, up_edge = pc - pa;
    const T width = glm::length(right_edge), height = glm::length(up_edge);
    if (!(width > T(0)) || !(height > T(0)) || !std::isfinite(width * height)) {
        return detail::error<T>("screen_projection", "screen edges must be non-zero and finite",
                                {{"width", width}, {"height", height}});
    }
    const Vec3<T> vr = right_edge / width, vu = up_edge / height;
    const T cosine = glm::dot(vr, vu);
    const T tolerance = perpendicular_tolerance<T>();
    if (!(std::abs(cosine) <= tolerance)) {
        return detail::error<T>("screen_projection",
                                "screen edges lower_right - lower_left and upper_left - lower_left must be "
                                "perpendicular (|cos| <= tolerance)",
                                {{"cos", cosine}, {"tolerance", tolerance}});
    }
    const Vec3<T> vn = glm::normalize(glm::cross(vr, vu));
    const Vec3<T> va = pa - pe, vb = pb - pe, vc = pc - pe;
    const T distance = glm::dot(vn, pe - pa);
    if (!(distance > detail::degenerate_ratio<T>() * (width + height))) {
        return detail::error<T>("screen_projection",
                                std::abs(distance) <= detail::degenerate_ratio<T>() * (width + height)
                                    ? "eye must not lie in the screen's plane"
                                    : "eye must be in front of the screen (the side (lower_right - lower_left) x "
                                      "(upper_left - lower_left) points to)",
                                {{"eye_distance", distance}});
    }
    if (!(near_m > T(0)) || !std::isfinite(near_m)) {
        return detail::error<T>("screen_projection", "near must be finite and > 0", {{"near", near_m}});
    }
    const T scale = near_m / distance;
    const T left = glm::dot(vr, va) * scale, right = glm::dot(vr, vb) * scale;
    const T bottom = glm::dot(vu, va) * scale, top = glm::dot(vu, vc) * scale;
    return detail::window_camera(detail::WindowCamera<T>{vr, vu, vn, pe, left, right, bottom, top, near_m, far_m}, depth,
                                 "frustum::screen_projection()");
}

template Result<MatrixPair<float>> screen_projection(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&,
                                                     const Vec3<float>&, float, std::optional<float>, DepthRange);
template Result<MatrixPair<double>> screen_projection(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&,
                                                      const Vec3<double>&, double, std::optional<double>,
                                                      DepthRange);

} // namespace frustum
