#include "frustum/projection.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/finite.hpp"
#include "frustum/detail/tolerances.hpp"
#include "frustum/detail/pair_factory.hpp"
#include "frustum/detail/plane_intersection.hpp"
#include "frustum/matrix_rows.hpp"

#include <cmath>
#include <limits>

namespace frustum {

namespace {

using detail::finite;

// Depth row coefficients: clip z = A z_eye + B (perspective, w = -z_eye).
template <class T>
struct PerspectiveDepth {
    T a, b;
};

template <class T>
PerspectiveDepth<T> perspective_depth(T near_m, std::optional<T> far_m, DepthRange depth) {
    const T zn = clip_z_near<T>(depth);
    const T zf = clip_z_far<T>(depth);
    if (!far_m) {
        return {-zf, -near_m * (zf - zn)};
    }
    const T f = *far_m;
    return {-(zf * f - zn * near_m) / (f - near_m), -near_m * f * (zf - zn) / (f - near_m)};
}

} // namespace

template <class T>
Result<MatrixPair<T>> perspective(T fovy_rad, T aspect, T near_m, std::optional<T> far_m, DepthRange depth) {
    const T pi = T(3.14159265358979323846);
    if (!finite(fovy_rad) || !(fovy_rad > T(0)) || !(fovy_rad < pi)) {
        return detail::error<T>("perspective", "fovy_rad must be in (0, pi)", {{"fovy_rad", fovy_rad}});
    }
    if (!finite(aspect) || !(aspect > T(0))) {
        return detail::error<T>("perspective", "aspect must be > 0 and finite", {{"aspect", aspect}});
    }
    if (!finite(near_m) || !(near_m > T(0))) {
        return detail::error<T>("perspective", "near must be > 0 and finite", {{"near", near_m}});
    }
    if (far_m && (!finite(*far_m) || !(*far_m > near_m))) {
        return detail::error<T>("perspective", "far must be finite and > near (or infinite_far)",
                                {{"near", near_m}, {"far", *far_m}});
    }
    const T top = near_m * std::tan(fovy_rad / T(2));
    const T right = top * aspect;
    if (!finite(top) || !finite(right) || !(right > T(0))) {
        return detail::error<T>("perspective", "near-plane half size is not finite and positive",
                                {{"top", top}, {"right", right}});
    }
    auto pair = off_axis(-right, right, -top, top, near_m, far_m, depth);
    if (!pair) {
        // Only representability can fail here; say which call the user made.
        return pair.take_error_in("frustum::perspective()");
    }
    return pair;
}

template <class T>
Result<MatrixPair<T>> off_axis(T left, T right, T bottom, T top, T near_m, std::optional<T> far_m,
                               DepthRange depth) {
    if (!finite(left) || !finite(right) || !finite(bottom) || !finite(top)) {
        return detail::error<T>("off_axis", "left, right, bottom, top must be finite",
                                {{"left", left}, {"right", right}, {"bottom", bottom}, {"top", top}});
    }
    if (!(right > left) || !(top > bottom)) {
        return detail::error<T>("off_axis", "need left < right and bottom < top",
                                {{"left", left}, {"right", right}, {"bottom", bottom}, {"top", top}});
    }
    if (!finite(near_m) || !(near_m > T(0))) {
        return detail::error<T>("off_axis", "near must be > 0 and finite", {{"near", near_m}});
    }
    if (far_m && (!finite(*far_m) || !(*far_m > near_m))) {
        return detail::error<T>("off_axis", "far must be finite and > near (or infinite_far)",
                                {{"near", near_m}, {"far", *far_m}});
    }
    const T sx = T(2) * near_m / (right - left);
    const T sy = T(2) * near_m / (top - bottom);
    const T cx = (right + left) / (right - left);
    const T cy = (top + bottom) / (top - bottom);
    const auto [a, b] = perspective_depth(near_m, far_m, depth);
    // Every entry of both matrices must be representable: reject underflow
    // to 0 (1/sx) as well as overflow.
    const T min_normal = std::numeric_limits<T>::min();
    if (!finite(sx) || !finite(sy) || !finite(cx) || !finite(cy) || !finite(a) || !finite(b) ||
        !(sx > min_normal) || !(sy > min_normal) || !(std::abs(b) > min_normal) || !finite(T(1) / sx) ||
        !finite(T(1) / sy) || !finite(T(1) / b) || !finite(cx / sx) || !finite(cy / sy) || !finite(a / b)) {
        return detail::error<T>("off_axis", "frustum too thin or too deep to represent",
                                {{"near", near_m}, {"far", far_m.value_or(std::numeric_limits<T>::infinity())}});
    }

    // The matrix drawn in projection.hpp, and its closed-form inverse:
    // z = -W, w = (Z + A W)/B, x = (X + cx W)/sx, y = (Y + cy W)/sy.
    const T o = T(0), one = T(1);
    const Mat4<T> m = from_rows<T>({sx, o, cx, o},
                                   {o, sy, cy, o},
                                   {o, o, a, b},
                                   {o, o, -one, o});
    const Mat4<T> inv = from_rows<T>({one / sx, o, o, cx / sx},
                                     {o, one / sy, o, cy / sy},
                                     {o, o, o, -one},
                                     {o, o, one / b, a / b});
    return detail::PairFactory::make(m, inv, depth, false);
}

template <class T>
Result<MatrixPair<T>> orthographic(T left, T right, T bottom, T top, T near_m, T far_m, DepthRange depth) {
    if (!finite(left) || !finite(right) || !finite(bottom) || !finite(top) || !finite(near_m) ||
        !finite(far_m)) {
        return detail::error<T>("orthographic", "all bounds must be finite",
                                {{"left", left}, {"right", right}, {"bottom", bottom}, {"top", top},
                                 {"near", near_m}, {"far", far_m}});
    }
    if (!(right > left) || !(top > bottom) || !(far_m > near_m)) {
        return detail::error<T>("orthographic", "need left < right, bottom < top and near < far",
                                {{"left", left}, {"right", right}, {"bottom", bottom}, {"top", top},
                                 {"near", near_m}, {"far", far_m}});
    }
    const T zn = clip_z_near<T>(depth);
    const T zf = clip_z_far<T>(depth);
    const T sx = T(2) / (right - left);
    const T sy = T(2) / (top - bottom);
    const T tx = -(right + left) / (right - left);
    const T ty = -(top + bottom) / (top - bottom);
    // clip z = A z_eye + B with z_eye = -near -> zn, -far -> zf.
    const T a = -(zf - zn) / (far_m - near_m);
    const T b = zn + a * near_m;
    const T min_normal = std::numeric_limits<T>::min();
    if (!finite(sx) || !finite(sy) || !finite(a) || !finite(b) || !finite(tx) || !finite(ty) ||
        !(sx > min_normal) || !(sy > min_normal) || !(std::abs(a) > min_normal) || !finite(T(1) / sx) ||
        !finite(T(1) / sy) || !finite(T(1) / a) || !finite(tx / sx) || !finite(ty / sy) || !finite(b / a)) {
        return detail::error<T>("orthographic", "box too thin to represent",
                                {{"near", near_m}, {"far", far_m}});
    }

    // The box matrix (scale and shift per axis) and its closed-form inverse.
    const T o = T(0), one = T(1);
    const Mat4<T> m = from_rows<T>({sx, o, o, tx},
                                   {o, sy, o, ty},
                                   {o, o, a, b},
                                   {o, o, o, one});
    const Mat4<T> inv = from_rows<T>({one / sx, o, o, -tx / sx},
                                     {o, one / sy, o, -ty / sy},
                                     {o, o, one / a, -b / a},
                                     {o, o, o, one});
    return detail::PairFactory::make(m, inv, depth, false);
}

template <class T>
RigidTransform<T> RigidTransform<T>::from_rotation_translation(const Mat3<T>& rotation, const Vec3<T>& translation) {
    RigidTransform<T> rigid;
    rigid.matrix = Mat4<T>(rotation);
    rigid.matrix[3] = Vec4<T>(translation, T(1));
    const Mat3<T> rotation_t = glm::transpose(rotation);
    rigid.inverse = Mat4<T>(rotation_t);
    rigid.inverse[3] = Vec4<T>(-(rotation_t * translation), T(1));
    return rigid;
}

template <class T>
Result<RigidTransform<T>> look_at(const Vec3<T>& eye, const Vec3<T>& target, const Vec3<T>& up) {
    if (!detail::finite3(eye) || !detail::finite3(target) || !detail::finite3(up)) {
        return detail::error_text("look_at", "eye, target and up must be finite",
                                  detail::vector_text(eye) + " " + detail::vector_text(target) + " " +
                                      detail::vector_text(up));
    }
    const Vec3<T> forward_unnormalized = target - eye;
    const T distance = glm::length(forward_unnormalized);
    if (!(distance > T(0))) {
        return detail::error_text("look_at", "eye must differ from target", "eye=" + detail::vector_text(eye));
    }
    if (!finite(distance)) {
        return detail::error_text("look_at", "eye and target are too far apart to represent",
                                  "eye=" + detail::vector_text(eye) + " target=" + detail::vector_text(target));
    }
    const Vec3<T> forward = forward_unnormalized / distance;
    const Vec3<T> side_unnormalized = glm::cross(forward, up);
    const T side_length = glm::length(side_unnormalized);
    const T up_length = glm::length(up);
    if (!(side_length > detail::degenerate_ratio<T>() * up_length) || !(up_length > T(0))) {
        return detail::error_text("look_at", "up must be non-zero and not parallel to the viewing direction",
                                  "up=" + detail::vector_text(up) + " direction=" + detail::vector_text(forward));
    }
    const Vec3<T> side = side_unnormalized / side_length;
    const Vec3<T> true_up = glm::cross(side, forward);
    // Rows of the rotation are the camera axes (x = side, y = up, z = -forward).
    Mat3<T> rotation;
    for (int c = 0; c < 3; ++c) {
        rotation[c] = Vec3<T>(side[c], true_up[c], -forward[c]);
    }
    return RigidTransform<T>::from_rotation_translation(rotation, -(rotation * eye));
}

template <class T>
MatrixPair<T> compose(const MatrixPair<T>& projection, const RigidTransform<T>& view) {
    return detail::PairFactory::keep_sign(Mat4<T>(projection.matrix() * view.matrix),
                                     Mat4<T>(view.inverse * projection.inverse()), projection.depth(),
                                     projection.flips_winding());
}

template <class T>
Result<MatrixPair<T>> from_matrix(const Mat4<T>& matrix, DepthRange depth) {
    T largest = T(0);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!finite(matrix[c][r])) {
                return detail::error<T>("from_matrix", "every entry must be finite",
                                        {{"column", T(c)}, {"row", T(r)}, {"value", matrix[c][r]}});
            }
            largest = std::max(largest, std::abs(matrix[c][r]));
        }
    }
    const std::optional<Mat4<T>> inv = detail::inverse_from_rows(matrix);
    if (!inv) {
        return detail::error<T>("from_matrix", "matrix is singular or too ill-conditioned to invert",
                                {{"largest_entry", largest}});
    }
    return detail::PairFactory::make(matrix, *inv, depth, false);
}

#define FRUSTUM_INSTANTIATE(T)                                                                                   \
    template Result<MatrixPair<T>> perspective(T, T, T, std::optional<T>, DepthRange);                            \
    template Result<MatrixPair<T>> off_axis(T, T, T, T, T, std::optional<T>, DepthRange);                         \
    template Result<MatrixPair<T>> orthographic(T, T, T, T, T, T, DepthRange);                                    \
    template struct RigidTransform<T>;                                                                            \
    template Result<RigidTransform<T>> look_at(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&);                   \
    template MatrixPair<T> compose(const MatrixPair<T>&, const RigidTransform<T>&);                               \
    template Result<MatrixPair<T>> from_matrix(const Mat4<T>&, DepthRange);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
