#include "frustum/portal.hpp"

#include "frustum/detail/portal_carry.hpp"
#include "frustum/detail/portal_preamble.hpp"
#include "frustum/oblique_clip.hpp"
#include "frustum/projection.hpp"

namespace frustum {

namespace {

// H = diag(-1, 1, -1, 1): the half turn about y, its own inverse.
template <class T>
RigidTransform<T> half_turn() {
    RigidTransform<T> h;
    h.matrix[0][0] = T(-1);
    h.matrix[2][2] = T(-1);
    h.inverse = h.matrix;
    return h;
}

} // namespace

namespace detail {

template <class T>
Result<RigidTransform<T>> portal_carry(const Frame<T>& entry, const Frame<T>& exit, const char* function) {
    const auto f_entry = frame_to_world(entry, function, "entry");
    if (!f_entry) {
        return f_entry.take_error();
    }
    const auto f_exit = frame_to_world(exit, function, "exit");
    if (!f_exit) {
        return f_exit.take_error();
    }
    // T = F_entry H F_exit^-1, T^-1 = F_exit H F_entry^-1.
    return *f_entry * half_turn<T>() * inverse(*f_exit);
}

template Result<RigidTransform<float>> portal_carry(const Frame<float>&, const Frame<float>&, const char*);
template Result<RigidTransform<double>> portal_carry(const Frame<double>&, const Frame<double>&, const char*);

} // namespace detail

template <class T>
Result<RigidTransform<T>> portal_transform(const Frame<T>& entry, const Frame<T>& exit) {
    return detail::portal_carry(entry, exit, "portal_transform");
}

template <class T>
Result<MatrixPair<T>> portal(const MatrixPair<T>& pair, const Frame<T>& entry, const Frame<T>& exit) {
    const auto carried = detail::carried_through_portal(pair, entry, exit, "portal"); // M T, T^-1 M^-1
    if (!carried) {
        return carried.take_error();
    }
    auto clipped = clip_oblique(*carried, frame_plane(exit));
    if (!clipped) {
        return clipped.take_error_in("frustum::portal()");
    }
    return clipped;
}

#define FRUSTUM_INSTANTIATE(T)                                                                    \
    template Result<RigidTransform<T>> portal_transform(const Frame<T>&, const Frame<T>&);        \
    template Result<MatrixPair<T>> portal(const MatrixPair<T>&, const Frame<T>&, const Frame<T>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
