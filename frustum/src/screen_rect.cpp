#include "frustum/screen_rect.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/finite.hpp"
#include "frustum/queries.hpp"

#include <algorithm>
#include <cmath>

namespace frustum {

namespace {

// Keeps the part of `polygon` where dot(plane, h) >= 0 (Sutherland-Hodgman).
template <class T>
void clip_polygon(std::vector<Vec4<T>>& polygon, std::vector<Vec4<T>>& scratch, const Vec4<T>& plane) {
    scratch.clear();
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec4<T>& a = polygon[i];
        const Vec4<T>& b = polygon[(i + 1) % n];
        const T da = glm::dot(plane, a), db = glm::dot(plane, b);
        if (da >= T(0)) {
            scratch.push_back(a);
        }
        if ((da >= T(0)) != (db >= T(0))) {
            const T t = da / (da - db); // in [0, 1]: the signs differ
            scratch.push_back(a + t * (b - a));
        }
    }
    polygon.swap(scratch);
}

// `width`, lowered by an ulp at a time until x + width <= limit (crop's own
// test), so rounding never puts the rectangle outside the image.
template <class T>
T fit_width(T x, T width, T limit) {
    while (x + width > limit && width > T(0)) {
        width = std::nextafter(width, T(0));
    }
    return width;
}

} // namespace

template <class T>
Result<std::optional<CropRect<T>>> screen_rect(const MatrixPair<T>& pair, const std::vector<Vec3<T>>& polygon,
                                               T width_px, T height_px) {
    if (!std::isfinite(width_px) || !std::isfinite(height_px) || !(width_px > T(0)) || !(height_px > T(0))) {
        return detail::error<T>("screen_rect", "image sizes must be finite and > 0",
                                {{"width_px", width_px}, {"height_px", height_px}});
    }
    if (polygon.size() < 3) {
        return detail::error<T>("screen_rect", "polygon needs at least 3 points",
                                {{"points", T(polygon.size())}});
    }
    std::vector<Vec4<T>> clip;
    clip.reserve(polygon.size() + 6);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3<T>& p = polygon[i];
        if (!detail::finite3(p)) {
            return detail::error_text("screen_rect", "polygon points must be finite",
                                      "point " + std::to_string(i) + "=" + detail::vector_text(p));
        }
        clip.push_back(pair.matrix() * Vec4<T>(p, T(1)));
    }
    // The frustum's planes in clip space (raw_planes' rows, eq. 1).
    const DepthRange depth = pair.depth();
    const T s = clip_z_span<T>(depth) > T(0) ? T(1) : T(-1);
    const T z_near = clip_z_near<T>(depth), z_far = clip_z_far<T>(depth);
    Vec4<T> planes[6] = {
        Vec4<T>(T(0), T(0), s, -s * z_near), // near first: nothing behind the eye reaches the sides
        Vec4<T>(T(1), T(0), T(0), T(1)),  Vec4<T>(T(-1), T(0), T(0), T(1)),
        Vec4<T>(T(0), T(1), T(0), T(1)),  Vec4<T>(T(0), T(-1), T(0), T(1)),
        Vec4<T>(T(0), T(0), -s, s * z_far),
    };
    const int plane_count = raw_planes(pair).far ? 6 : 5;
    std::vector<Vec4<T>> scratch;
    scratch.reserve(clip.size() + 6);
    for (int i = 0; i < plane_count && !clip.empty(); ++i) {
        clip_polygon(clip, scratch, planes[i]);
    }
    T x_min = T(1), x_max = T(-1), y_min = T(1), y_max = T(-1);
    for (const Vec4<T>& h : clip) {
        if (!(h.w > T(0))) {
            continue; // only the eye point itself (x = y = 0) can survive with w = 0
        }
        const T x = std::clamp(h.x / h.w, T(-1), T(1)), y = std::clamp(h.y / h.w, T(-1), T(1));
        x_min = std::min(x_min, x);
        x_max = std::max(x_max, x);
        y_min = std::min(y_min, y);
        y_max = std::max(y_max, y);
    }
    const T x0 = (x_min + T(1)) * T(0.5) * width_px, x1 = (x_max + T(1)) * T(0.5) * width_px;
    const T y0 = (y_min + T(1)) * T(0.5) * height_px, y1 = (y_max + T(1)) * T(0.5) * height_px;
    if (!(x1 > x0) || !(y1 > y0)) {
        return std::optional<CropRect<T>>();
    }
    CropRect<T> rect;
    rect.x = x0;
    rect.y = y0;
    rect.width = fit_width(x0, x1 - x0, width_px);
    rect.height = fit_width(y0, y1 - y0, height_px);
    rect.full_width = width_px;
    rect.full_height = height_px;
    if (!(rect.width > T(0)) || !(rect.height > T(0))) {
        return std::optional<CropRect<T>>();
    }
    return std::optional<CropRect<T>>(rect);
}

template <class T>
std::optional<CropRect<T>> intersect(const CropRect<T>& a, const CropRect<T>& b) {
    if (a.full_width != b.full_width || a.full_height != b.full_height) {
        return std::nullopt;
    }
    const T x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
    const T x1 = std::min(a.x + a.width, b.x + b.width), y1 = std::min(a.y + a.height, b.y + b.height);
    if (!(x1 > x0) || !(y1 > y0)) {
        return std::nullopt;
    }
    CropRect<T> r;
    r.x = x0;
    r.y = y0;
    r.width = fit_width(x0, x1 - x0, a.full_width);
    r.height = fit_width(y0, y1 - y0, a.full_height);
    r.full_width = a.full_width;
    r.full_height = a.full_height;
    return r;
}

#define FRUSTUM_INSTANTIATE(T)                                                                              \
    template Result<std::optional<CropRect<T>>> screen_rect(const MatrixPair<T>&, const std::vector<Vec3<T>>&, \
                                                            T, T);                                           \
    template std::optional<CropRect<T>> intersect(const CropRect<T>&, const CropRect<T>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
