#include "reference/curved_reference.hpp"

#include <frustum/depth_range.hpp>
#include <image/compare.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>

namespace reference {
namespace {

struct Triangle {
    glm::dvec3 a, ab, ac;       // world corner and edges
    glm::dvec3 front;           // cross(ab, ac), flipped for a mirroring model matrix: GL's front side
    glm::dvec3 na, nb, nc;      // world normals (cofactor matrix, not normalized), when has_normals
    glm::dvec4 ca, cb, cc;      // base colour factor x vertex colour
    bool has_normals = false;
    bool double_sided = false;
};

struct Box {
    glm::dvec3 min, max;
};

struct InstanceTriangles {
    Box box;
    std::vector<Triangle> triangles;
};

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    const Triangle* triangle = nullptr;
    double b1 = 0, b2 = 0; // barycentric weights of b and c
};

// Triangle lists of every primitive mode with triangles, as GL assembles them.
std::vector<std::array<std::uint32_t, 3>> assemble(const scene::Primitive& p) {
    std::vector<std::array<std::uint32_t, 3>> out;
    const auto& ix = p.indices;
    switch (p.mode) {
    case scene::PrimitiveMode::Triangles:
        for (std::size_t i = 0; i + 2 < ix.size(); i += 3) out.push_back({ix[i], ix[i + 1], ix[i + 2]});
        break;
    case scene::PrimitiveMode::TriangleStrip:
        for (std::size_t i = 0; i + 2 < ix.size(); ++i)
            out.push_back(i % 2 == 0 ? std::array<std::uint32_t, 3>{ix[i], ix[i + 1], ix[i + 2]}
                                     : std::array<std::uint32_t, 3>{ix[i + 1], ix[i], ix[i + 2]});
        break;
    case scene::PrimitiveMode::TriangleFan:
        for (std::size_t i = 1; i + 1 < ix.size(); ++i) out.push_back({ix[0], ix[i], ix[i + 1]});
        break;
    default: break; // points and lines: not hit by rays
    }
    return out;
}

// The cofactor matrix, signed: scene_pass.cpp's normal matrix.
glm::dmat3 normal_matrix(const glm::dmat4& model) {
    const glm::dmat3 a(model);
    const glm::dmat3 cofactor(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
    return glm::determinant(a) < 0.0 ? -cofactor : cofactor;
}

frustum::Result<std::vector<InstanceTriangles>> collect(const scene::Scene& scene) {
    const int skip = scene.mirror ? scene.mirror->instance : -1;
    std::vector<InstanceTriangles> out;
    for (std::size_t n = 0; n < scene.instances.size(); ++n) {
        if (static_cast<int>(n) == skip) {
            continue;
        }
        const scene::Instance& instance = scene.instances[n];
        const glm::dmat4 model(instance.world);
        const glm::dmat3 normals = normal_matrix(model);
        const bool flips = glm::determinant(glm::dmat3(model)) < 0.0;
        InstanceTriangles group;
        group.box = {glm::dvec3(std::numeric_limits<double>::infinity()),
                     glm::dvec3(-std::numeric_limits<double>::infinity())};
        for (const scene::Primitive& p : scene.meshes[static_cast<std::size_t>(instance.mesh)].primitives) {
            const scene::Material material =
                p.material >= 0 ? scene.materials[static_cast<std::size_t>(p.material)] : scene::Material{};
            if (material.base_color_texture >= 0) {
                return frustum::Error{"reference::trace_curved_frame(): material '" + material.name +
                                      "' has a texture; the reference shades untextured materials only"};
            }
            const auto world = [&](std::uint32_t i) { return glm::dvec3(model * glm::dvec4(p.positions[i], 1.0)); };
            const auto color = [&](std::uint32_t i) {
                return glm::dvec4(material.base_color_factor) *
                       (p.colors.empty() ? glm::dvec4(1.0) : glm::dvec4(p.colors[i]));
            };
            const auto normal = [&](std::uint32_t i) {
                return p.normals.empty() ? glm::dvec3(0.0) : normals * glm::dvec3(p.normals[i]);
            };
            for (const auto& [i, j, k] : assemble(p)) {
                Triangle t;
                t.a = world(i);
                t.ab = world(j) - t.a;
                t.ac = world(k) - t.a;
                t.front = (flips ? -1.0 : 1.0) * glm::cross(t.ab, t.ac);
                t.na = normal(i), t.nb = normal(j), t.nc = normal(k);
                t.ca = color(i), t.cb = color(j), t.cc = color(k);
                t.has_normals = !p.normals.empty();
                t.double_sided = material.double_sided;
                for (const glm::dvec3& v : {t.a, t.a + t.ab, t.a + t.ac}) {
                    group.box.min = glm::min(group.box.min, v);
                    group.box.max = glm::max(group.box.max, v);
                }
                group.triangles.push_back(t);
            }
        }
        if (!group.triangles.empty()) {
            out.push_back(std::move(group));
        }
    }
    return out;
}

// Slab test: does the ray meet the box before t_max?
bool meets(const Box& box, const glm::dvec3& origin, const glm::dvec3& inverse_direction, double t_max) {
    double t0 = 0.0, t1 = t_max;
    for (int a = 0; a < 3; ++a) {
        double near = (box.min[a] - origin[a]) * inverse_direction[a];
        double far = (box.max[a] - origin[a]) * inverse_direction[a];
        if (near > far) std::swap(near, far);
        if (std::isnan(near) || std::isnan(far)) continue; // origin on a slab face, direction parallel
        t0 = std::max(t0, near);
        t1 = std::min(t1, far * (1.0 + 1e-12));
        if (t0 > t1) return false;
    }
    return true;
}

// Nearest visible triangle (Moeller-Trumbore); back faces of single-sided
// materials are culled, as set_face_state() does on the GPU.
Hit trace(const std::vector<InstanceTriangles>& scene, const glm::dvec3& origin, const glm::dvec3& direction,
          double t_min) {
    Hit best;
    const glm::dvec3 inverse(1.0 / direction.x, 1.0 / direction.y, 1.0 / direction.z);
    for (const InstanceTriangles& group : scene) {
        if (!meets(group.box, origin, inverse, best.t)) {
            continue;
        }
        for (const Triangle& t : group.triangles) {
            if (!t.double_sided && !(glm::dot(t.front, direction) < 0.0)) {
                continue;
            }
            const glm::dvec3 p = glm::cross(direction, t.ac);
            const double det = glm::dot(t.ab, p);
            if (det == 0.0) continue;
            const double inv_det = 1.0 / det;
            const glm::dvec3 s = origin - t.a;
            const double b1 = glm::dot(s, p) * inv_det;
            if (b1 < 0.0 || b1 > 1.0) continue;
            const glm::dvec3 q = glm::cross(s, t.ab);
            const double b2 = glm::dot(direction, q) * inv_det;
            if (b2 < 0.0 || b1 + b2 > 1.0) continue;
            const double dist = glm::dot(t.ac, q) * inv_det;
            if (dist > t_min && dist < best.t) {
                best = {dist, &t, b1, b2};
            }
        }
    }
    return best;
}

double linear_to_srgb(double c) { return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

// scene.frag for the hit, as 8-bit sRGB (before any tint).
glm::dvec3 shade(const Hit& hit, const glm::dvec3& direction, const render::Lighting& lighting) {
    const Triangle& t = *hit.triangle;
    const double b0 = 1.0 - hit.b1 - hit.b2;
    const glm::dvec4 base = b0 * t.ca + hit.b1 * t.cb + hit.b2 * t.cc;
    const bool front_facing = glm::dot(t.front, direction) < 0.0;
    glm::dvec3 n;
    if (t.has_normals) {
        n = glm::normalize(b0 * t.na + hit.b1 * t.nb + hit.b2 * t.nc);
        if (t.double_sided && !front_facing) n = -n;
    } else {
        // cross(dFdx, dFdy) of an unmirrored view faces the viewer.
        n = glm::normalize(glm::cross(t.ab, t.ac));
        if (glm::dot(n, direction) > 0.0) n = -n;
    }
    const glm::dvec3 to_light = glm::normalize(glm::dvec3(lighting.to_light));
    const double light = lighting.ambient + lighting.diffuse * std::max(glm::dot(n, to_light), 0.0);
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) {
        out[c] = std::round(linear_to_srgb(std::clamp(base[c] * light, 0.0, 1.0)) * 255.0);
    }
    return out;
}

glm::dvec3 clear_8bit(const glm::vec4& clear) { return glm::round(glm::dvec3(clear) * 255.0); }

image::Rgba to_rgba(const glm::dvec3& c) {
    const auto channel = [](double v) { return static_cast<std::uint8_t>(std::clamp(std::round(v), 0.0, 255.0)); };
    return {channel(c.r), channel(c.g), channel(c.b), 255};
}

// The ray through a pixel's centre (x from the left, y from the top),
// starting on the camera's near plane.
class PixelRays {
public:
    PixelRays(const frustum::MatrixPair<float>& camera, int width_px, int height_px)
        : inverse_(camera.inverse()), z_near_(frustum::clip_z_near<double>(camera.depth())),
          z_mid_(frustum::clip_z_mid<double>(camera.depth())), width_(width_px), height_(height_px) {}

    std::pair<glm::dvec3, glm::dvec3> operator()(int x, int y) const {
        // NDC y grows upwards, image rows downwards.
        const double ndc_x = (x + 0.5) / width_ * 2.0 - 1.0;
        const double ndc_y = 1.0 - (y + 0.5) / height_ * 2.0;
        const glm::dvec3 origin = unproject(ndc_x, ndc_y, z_near_);
        return {origin, glm::normalize(unproject(ndc_x, ndc_y, z_mid_) - origin)};
    }

private:
    glm::dvec3 unproject(double x, double y, double z) const {
        const glm::dvec4 p = inverse_ * glm::dvec4(x, y, z, 1.0);
        return glm::dvec3(p) / p.w;
    }
    glm::dmat4 inverse_;
    double z_near_, z_mid_;
    int width_, height_;
};

glm::dvec3 reflect_about(const glm::dvec3& d, const glm::dvec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

} // namespace

frustum::Result<TracedFrame> trace_curved_frame(const scene::Scene& scene, const plan::CurvedMirror& mirror,
                                                const frustum::MatrixPair<float>& camera, int width_px, int height_px,
                                                const TraceSettings& settings) {
    if (width_px < 1 || height_px < 1) {
        return frustum::Error{"reference::trace_curved_frame(): the image must be at least 1x1, got " +
                              std::to_string(width_px) + "x" + std::to_string(height_px)};
    }
    auto triangles = collect(scene);
    if (!triangles) {
        return triangles.take_error();
    }
    const PixelRays rays(camera, width_px, height_px);
    TracedFrame out;
    out.picture = image::make_image(width_px, height_px, {0, 0, 0, 255});
    out.on_mirror.assign(static_cast<std::size_t>(width_px * height_px), false);
    for (int y = 0; y < height_px; ++y) {
        for (int x = 0; x < width_px; ++x) {
            const auto [origin, direction] = rays(x, y);
            const Hit first = trace(*triangles, origin, direction, 0.0);
            const auto cap = mirror.intersect(origin, direction, 0.0);
            glm::dvec3 color;
            if (cap && cap->t < first.t) {
                const glm::dvec3 surface = origin + cap->t * direction;
                const glm::dvec3 normal = mirror.at(cap->uv.x, cap->uv.y).normal;
                const glm::dvec3 reflected = reflect_about(direction, normal);
                const Hit second = trace(*triangles, surface, reflected, 1e-6);
                const glm::dvec3 seen =
                    second.triangle ? shade(second, reflected, settings.lighting) : clear_8bit(settings.clear_color);
                color = glm::round(seen * glm::dvec3(settings.tint));
                out.on_mirror[static_cast<std::size_t>(y * width_px + x)] = true;
                ++out.mirror_pixels;
            } else {
                color = first.triangle ? shade(first, direction, settings.lighting) : clear_8bit(settings.clear_color);
            }
            image::set_pixel(out.picture, x, y, to_rgba(color));
        }
    }
    return out;
}

RayAngleError lookup_ray_error(const plan::CurvedMirror& mirror, const plan::CurvedPlan& plan,
                               const frustum::MatrixPair<float>& camera, int width_px, int height_px) {
    const PixelRays rays(camera, width_px, height_px);
    RayAngleError e;
    double sum = 0.0;
    for (int y = 0; y < height_px; ++y) {
        for (int x = 0; x < width_px; ++x) {
            const auto [origin, direction] = rays(x, y);
            const auto cap = mirror.intersect(origin, direction, 0.0);
            if (!cap) {
                continue;
            }
            const auto cell = [&](double t) { return std::clamp(static_cast<int>(t * plan.grid), 0, plan.grid - 1); };
            const plan::PatchFrustum& patch =
                plan.patches[static_cast<std::size_t>(cell(cap->uv.y) * plan.grid + cell(cap->uv.x))];
            if (!patch.pair) {
                continue;
            }
            const glm::dvec3 surface = origin + cap->t * direction;
            const glm::dvec3 exact = reflect_about(direction, mirror.at(cap->uv.x, cap->uv.y).normal);
            const double cosine = glm::dot(glm::normalize(surface - patch.origin), exact);
            const double degrees = glm::degrees(std::acos(std::clamp(cosine, -1.0, 1.0)));
            ++e.pixels;
            sum += degrees;
            e.max_deg = std::max(e.max_deg, degrees);
        }
    }
    e.mean_deg = e.pixels > 0 ? sum / e.pixels : 0.0;
    return e;
}

MirrorError compare_on_mask(const image::Image& rendered, const image::Image& traced, const std::vector<bool>& mask,
                            int threshold) {
    const image::Diff d = image::compare_masked(rendered, traced, mask, image::Channels::Rgb, threshold).value();
    return MirrorError{d.pixel_count, d.mean_abs, d.max_abs, d.fraction_over()};
}

} // namespace reference
