#include "plan/mirror_geometry.hpp"

#include <frustum/crop.hpp>
#include <frustum/mirror.hpp>
#include <frustum/queries.hpp>
#include <frustum/reflect.hpp>
#include <frustum/screen_rect.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace plan {
namespace {

constexpr const char* kPlan = "plan::plan_reflection(): ";
// Largest reflection texture side for the rectangle method (GL ES 3.0
// guarantees 2048; llvmpipe and current phones allow 4096 or more, and
// OffscreenTarget::create() checks the real limit).
constexpr int kMaxTextureSidePx = 4096;

std::array<glm::vec3, 4> corners(const scene::MirrorRect& m) {
    return {m.corner, m.corner + m.a1, m.corner + m.a1 + m.a2, m.corner + m.a2};
}

// Signed distance-like value to the near plane in clip space, >= 0 in front:
// N = s (m2 - z_n m3) (queries.hpp), evaluated on clip = M p.
float near_value(const glm::vec4& clip, frustum::DepthRange depth) {
    const float sign = frustum::clip_z_span<float>(depth) > 0.0f ? 1.0f : -1.0f;
    return sign * (clip.z - frustum::clip_z_near<float>(depth) * clip.w);
}

// NDC x, y in [-1, 1] -> pixels from the bottom-left.
glm::vec2 to_pixels(const glm::vec4& clip, int width_px, int height_px) {
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return (ndc * 0.5f + 0.5f) * glm::vec2(static_cast<float>(width_px), static_cast<float>(height_px));
}

frustum::CropRect<float> crop_rect(const PixelRect& r, int width_px, int height_px) {
    return {static_cast<float>(r.x),     static_cast<float>(r.y),        static_cast<float>(r.width),
            static_cast<float>(r.height), static_cast<float>(width_px), static_cast<float>(height_px)};
}

// Rectangle method: texture width along a2, height along a1, each the longer
// on-screen length of the two parallel edges, so a texel is never larger
// than a screen pixel. With a corner behind the near plane the lengths are
// unknown: then the screen rectangle's longer side for both.
glm::ivec2 rectangle_texture_size(const scene::MirrorRect& mirror, const frustum::MatrixPair<float>& camera,
                                  int width_px, int height_px, const PixelRect& screen_rect) {
    const auto points = corners(mirror);
    std::array<glm::vec2, 4> px{};
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::vec4 clip = camera.matrix() * glm::vec4(points[i], 1.0f);
        if (!(near_value(clip, camera.depth()) > 0.0f && clip.w > 0.0f)) {
            const int side = std::max(screen_rect.width, screen_rect.height);
            return {side, side};
        }
        px[i] = to_pixels(clip, width_px, height_px);
    }
    // Corners 0-1 and 3-2 run along a1; 0-3 and 1-2 along a2.
    const float along_a1 = std::max(glm::distance(px[0], px[1]), glm::distance(px[3], px[2]));
    const float along_a2 = std::max(glm::distance(px[0], px[3]), glm::distance(px[1], px[2]));
    const auto side = [](float length_px) {
        return std::clamp(static_cast<int>(std::ceil(length_px)), 1, kMaxTextureSidePx);
    };
    return {side(along_a2), side(along_a1)};
}

// The far distance for mirror_rectangle: beyond every corner of the bounds
// as seen from the reflected eye (1% and 1 cm of margin).
float reach_m(const scene::Bounds& bounds, const glm::vec3& from) {
    float farthest_m = 0.0f;
    for (const glm::vec3& corner : scene::corners(bounds)) {
        farthest_m = std::max(farthest_m, glm::distance(from, corner));
    }
    return farthest_m * 1.01f + 0.01f;
}

} // namespace

frustum::Plane<float> mirror_plane(const scene::MirrorRect& mirror) {
    const glm::vec3 normal = glm::normalize(glm::cross(mirror.a1, mirror.a2));
    return frustum::Plane<float>(glm::vec4(normal, -glm::dot(normal, mirror.corner)));
}

std::optional<frustum::CropRect<float>> whole_pixels(const frustum::CropRect<float>& r) {
    const float x0 = std::max(0.0f, std::floor(r.x)), y0 = std::max(0.0f, std::floor(r.y));
    const float x1 = std::min(r.full_width, std::ceil(r.x + r.width));
    const float y1 = std::min(r.full_height, std::ceil(r.y + r.height));
    if (!(x1 > x0 && y1 > y0)) {
        return std::nullopt;
    }
    return frustum::CropRect<float>{x0, y0, x1 - x0, y1 - y0, r.full_width, r.full_height};
}

PixelRect pixel_rect(const frustum::CropRect<float>& whole) {
    return {static_cast<int>(whole.x), static_cast<int>(whole.y), static_cast<int>(whole.width),
            static_cast<int>(whole.height)};
}

std::optional<PixelRect> pixels_seen(const frustum::MatrixPair<float>& camera, const std::vector<glm::vec3>& polygon,
                                     int width_px, int height_px) {
    const auto seen = frustum::screen_rect(camera, polygon, static_cast<float>(width_px), static_cast<float>(height_px));
    if (!seen || !*seen) {
        return std::nullopt;
    }
    const auto whole = whole_pixels(**seen);
    if (!whole) {
        return std::nullopt;
    }
    return pixel_rect(*whole);
}

std::optional<PixelRect> mirror_screen_rect(const scene::MirrorRect& mirror, const frustum::MatrixPair<float>& camera,
                                            int width_px, int height_px) {
    const auto points = corners(mirror);
    return pixels_seen(camera, std::vector<glm::vec3>(points.begin(), points.end()), width_px, height_px);
}

frustum::Result<std::optional<ReflectionView>> plan_reflection(const scene::MirrorRect& mirror,
                                                               const frustum::MatrixPair<float>& camera,
                                                               int width_px, int height_px, MirrorMethod method,
                                                               const scene::Bounds& bounds) {
    const frustum::Plane<float> plane = mirror_plane(mirror);
    // The eye as key_points() gives it (w > 0 when finite; a direction
    // pointing back when orthographic): positive means in front of the mirror.
    const glm::vec4 eye = frustum::key_points(camera).eye;
    if (!(plane.evaluate(eye) > 0.0f)) {
        return std::optional<ReflectionView>();
    }
    const auto rect = mirror_screen_rect(mirror, camera, width_px, height_px);
    if (!rect) {
        return std::optional<ReflectionView>();
    }
    const auto cropped = [&](const frustum::Result<frustum::MatrixPair<float>>& reflected)
        -> frustum::Result<std::optional<ReflectionView>> {
        if (!reflected) {
            return frustum::Error{kPlan + reflected.error()};
        }
        auto tight = frustum::crop(*reflected, crop_rect(*rect, width_px, height_px));
        if (!tight) {
            return frustum::Error{kPlan + tight.error()};
        }
        return std::optional<ReflectionView>(ReflectionView{*tight, rect->width, rect->height, *rect});
    };
    switch (method) {
    case MirrorMethod::Oblique: return cropped(frustum::mirror(camera, plane));
    case MirrorMethod::ReflectOnly: return cropped(frustum::reflect(camera, plane));
    case MirrorMethod::Rectangle: break;
    }
    const glm::vec4 eye_point = frustum::to_point(eye, frustum::infinity_tolerance<float>());
    if (eye_point.w != 1.0f) {
        return frustum::Error{std::string(kPlan) + "the rectangle method needs a finite eye (perspective camera)"};
    }
    const glm::vec3 eye_m(eye_point);
    const glm::vec3 reflected_eye = eye_m - 2.0f * plane.distance(eye_m) * plane.normal(); // eq. 30
    auto pair = frustum::mirror_rectangle<float>({mirror.corner, mirror.a1, mirror.a2}, eye_m,
                                                 reach_m(bounds, reflected_eye), frustum::MirrorFit::Exact,
                                                 frustum::DepthRange::ZeroToOne);
    if (!pair) {
        return frustum::Error{kPlan + pair.error()};
    }
    const glm::ivec2 size = rectangle_texture_size(mirror, camera, width_px, height_px, *rect);
    return std::optional<ReflectionView>(ReflectionView{*pair, size.x, size.y, *rect});
}

} // namespace plan
