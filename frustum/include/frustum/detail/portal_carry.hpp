// portal_transform() with the caller's function name in its errors (portal,
// culling_pair), defined in src/portal.cpp.
#pragma once

#include "frustum/result.hpp"
#include "frustum/rigid.hpp"

namespace frustum::detail {

template <class T>
Result<RigidTransform<T>> portal_carry(const Frame<T>& entry, const Frame<T>& exit, const char* function);

} // namespace frustum::detail
