#include "frustum/non_affine.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/reflect.hpp"

namespace frustum {

template <class T>
Result<NonAffineFrustum<T>> NonAffineFrustum<T>::from_planes(const Plane<T>& left, const Plane<T>& right,
                                                             const Plane<T>& bottom, const Plane<T>& top,
                                                             const Plane<T>& near, const Plane<T>& far,
                                                             const Vec3<T>& inside, DepthRange depth) {
    const Plane<T>* input[6] = {&left, &right, &bottom, &top, &near, &far};
    const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
    NonAffineFrustum frustum;
    frustum.depth_ = depth;
    for (int i = 0; i < 6; ++i) {
        auto unit = checked_unit_plane(*input[i], "NonAffineFrustum::from_planes");
        if (!unit) {
            return Error{unit.error() + " (" + names[i] + " plane)"};
        }
        frustum.planes_[i] = *unit;
        const T d = unit->distance(inside);
        if (!(d < T(0))) {
            return detail::error_text("NonAffineFrustum::from_planes",
                                      std::string("the inside point must be on the negative (inner) side of every "
                                                  "outward plane; it is not for the ") + names[i] + " plane",
                                      "distance=" + detail::number(d));
        }
    }
    return frustum;
}

template <class T>
Vec3<T> NonAffineFrustum<T>::denominators(const Vec3<T>& p) const {
    return Vec3<T>(planes_[0].distance(p) + planes_[1].distance(p), planes_[2].distance(p) + planes_[3].distance(p),
                   planes_[4].distance(p) + planes_[5].distance(p));
}

template <class T>
std::optional<Vec3<T>> NonAffineFrustum<T>::parameters(const Vec3<T>& p, T guard_m) const {
    const Vec3<T> den = denominators(p);
    if (!(den.x < -guard_m && den.y < -guard_m && den.z < -guard_m)) {
        return std::nullopt;
    }
    // eq. 36: d_l / (d_l + d_r), d_t / (d_t + d_b), d_n / (d_n + d_f)
    return Vec3<T>(planes_[0].distance(p) / den.x, planes_[3].distance(p) / den.y, planes_[4].distance(p) / den.z);
}

template <class T>
std::optional<Vec4<T>> NonAffineFrustum<T>::to_clip(const Vec3<T>& p, T guard_m) const {
    const auto uvs = parameters(p, guard_m);
    if (!uvs) {
        return std::nullopt;
    }
    const T z = clip_z_near<T>(depth_) + uvs->z * clip_z_span<T>(depth_);
    return Vec4<T>(T(2) * uvs->x - T(1), T(1) - T(2) * uvs->y, z, T(1));
}

template class NonAffineFrustum<float>;
template class NonAffineFrustum<double>;

} // namespace frustum
