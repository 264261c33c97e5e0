// What portal() and culling_pair(camera, entry, exit) do first, with the
// caller's function name in the errors: both frames valid (portal_carry()),
// the eye strictly on the entry portal's front side, then the camera carried
// through the portals, M T and T^-1 M^-1 (compose(), no inversion).
#pragma once

#include "frustum/detail/eye_side.hpp"
#include "frustum/detail/portal_carry.hpp"
#include "frustum/matrix_pair.hpp"
#include "frustum/portal.hpp"
#include "frustum/projection.hpp"
#include "frustum/result.hpp"

namespace frustum::detail {

template <class T>
Result<MatrixPair<T>> carried_through_portal(const MatrixPair<T>& camera, const Frame<T>& entry, const Frame<T>& exit,
                                             const char* function) {
    const auto carry = portal_carry(entry, exit, function);
    if (!carry) {
        return carry.take_error();
    }
    if (const auto error = eye_in_front(camera, frame_plane(entry), function, "entry_plane",
                                        "the eye must not lie in the entry portal's plane",
                                        "the eye must be on the entry portal's front (positive) side")) {
        return *error;
    }
    return compose(camera, *carry);
}

} // namespace frustum::detail
