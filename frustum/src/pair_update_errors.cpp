// The refusals of the hot pair updates (detail/pair_updates.hpp), out of
// line and cold so that no text is built, or even inlined, on the success
// path. Texts are pinned by tests/math/errors_test.cpp.
#include "frustum/detail/errors.hpp"
#include "frustum/detail/pair_updates.hpp"

#include <cmath>

namespace frustum::detail {

template <class T>
Error crop_rect_error(const CropRect<T>& r, const char* function) {
    const bool sizes_ok = r.full_width > T(0) && r.full_height > T(0) && r.width > T(0) && r.height > T(0);
    const bool finite = std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.width) &&
                        std::isfinite(r.height) && std::isfinite(r.full_width) && std::isfinite(r.full_height);
    return error<T>(function,
                    !finite     ? "crop rectangle must be finite"
                    : !sizes_ok ? "crop and image sizes must be > 0"
                                : "crop rectangle must lie inside the image",
                    {{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height},
                     {"full_width", r.full_width}, {"full_height", r.full_height}});
}

template <class T>
Error plane_error(const Vec4<T>& c, const char* function) {
    const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w);
    return error_text(function, finite ? "plane normal must be non-zero and finite" : "plane must be finite",
                      vector_text(c));
}

template Error crop_rect_error(const CropRect<float>&, const char*);
template Error crop_rect_error(const CropRect<double>&, const char*);
template Error plane_error(const Vec4<float>&, const char*);
template Error plane_error(const Vec4<double>&, const char*);

} // namespace frustum::detail
