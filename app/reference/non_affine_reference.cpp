#include "reference/non_affine_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace reference {
namespace {

struct Hit {
    double s = std::numeric_limits<double>::infinity();
    const plan::WorldPrimitive* primitive = nullptr;
    std::size_t first_index = 0; // of the triangle in primitive->indices
    double b1 = 0.0, b2 = 0.0;   // barycentric weights of its 2nd and 3rd vertex
    glm::dvec3 direction{0.0};   // along the pixel's line, towards larger s
};

std::uint8_t to_unorm8(double c) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

// scene.frag's linear_to_srgb().
double linear_to_srgb(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

class Caster {
public:
    Caster(const plan::WorldGeometry& geometry, const frustum::NonAffineFrustum<float>& frustum)
        : geometry_(geometry) {
        for (int i = 0; i < 6; ++i) {
            planes_[i] = glm::dvec4(frustum.plane(i).abcd);
        }
    }

    // The pixel centre (u, v) in [0, 1]^2 (v = 0 at the top): its line
    // anchor + t direction, or false when the two planes are parallel.
    bool line(double u, double v, glm::dvec3& anchor, glm::dvec3& direction) const {
        const glm::dvec4 p = (1.0 - u) * planes_[0] - u * planes_[1]; // d_l / (d_l + d_r) = u
        const glm::dvec4 q = (1.0 - v) * planes_[3] - v * planes_[2]; // d_t / (d_t + d_b) = v
        direction = glm::cross(glm::dvec3(p), glm::dvec3(q));
        const double length = glm::length(direction);
        if (!(length > 1e-12)) {
            return false;
        }
        direction /= length;
        // Rows p.xyz, q.xyz, direction: the point of the line nearest the origin.
        const glm::dmat3 rows_transposed(glm::dvec3(p), glm::dvec3(q), direction);
        anchor = glm::inverse(glm::transpose(rows_transposed)) * glm::dvec3(-p.w, -q.w, 0.0);
        return true;
    }

    Hit cast(const glm::dvec3& anchor, const glm::dvec3& direction) const {
        Hit best;
        for (const plan::WorldPrimitive& primitive : geometry_.primitives) {
            for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
                test(primitive, t, anchor, direction, best);
            }
        }
        return best;
    }

private:
    double distance(int plane, const glm::dvec3& x) const {
        return glm::dot(glm::dvec3(planes_[plane]), x) + planes_[plane].w;
    }

    // Moller-Trumbore against the whole line (t of either sign).
    void test(const plan::WorldPrimitive& primitive, std::size_t t, const glm::dvec3& anchor,
              const glm::dvec3& direction, Hit& best) const {
        const glm::dvec3 a(primitive.vertices[primitive.indices[t]].position);
        const glm::dvec3 e1 = glm::dvec3(primitive.vertices[primitive.indices[t + 1]].position) - a;
        const glm::dvec3 e2 = glm::dvec3(primitive.vertices[primitive.indices[t + 2]].position) - a;
        const glm::dvec3 pvec = glm::cross(direction, e2);
        const double det = glm::dot(e1, pvec);
        if (std::abs(det) < 1e-14) {
            return;
        }
        const glm::dvec3 tvec = anchor - a;
        const double b1 = glm::dot(tvec, pvec) / det;
        if (b1 < 0.0 || b1 > 1.0) {
            return;
        }
        const glm::dvec3 qvec = glm::cross(tvec, e1);
        const double b2 = glm::dot(direction, qvec) / det;
        if (b2 < 0.0 || b1 + b2 > 1.0) {
            return;
        }
        const glm::dvec3 x = anchor + (glm::dot(e2, qvec) / det) * direction;
        for (int i = 0; i < 6; ++i) {
            if (distance(i, x) > 1e-9) {
                return; // outside the frustum
            }
        }
        const double d_near = distance(4, x), d_far = distance(5, x);
        const double s = d_near / (d_near + d_far); // eq. 36, third coordinate
        // Towards larger s along the line: the sign of grad(s) . direction.
        const glm::dvec3 grad_s = glm::dvec3(planes_[4]) * d_far - glm::dvec3(planes_[5]) * d_near;
        const glm::dvec3 deeper = glm::dot(grad_s, direction) >= 0.0 ? direction : -direction;
        // Front faces are counter-clockwise on screen: their normal points
        // against the depth direction. The GPU culls single-sided back faces.
        if (!primitive.double_sided && glm::dot(glm::cross(e1, e2), deeper) >= 0.0) {
            return;
        }
        if (s < best.s) {
            best = Hit{s, &primitive, t, b1, b2, deeper};
        }
    }

    const plan::WorldGeometry& geometry_;
    glm::dvec4 planes_[6];
};

// scene.frag for the hit: base colour x vertex colour, ambient + diffuse.
image::Rgba shade(const Hit& hit, const render::Lighting& lighting) {
    const plan::WorldPrimitive& p = *hit.primitive;
    const plan::WorldVertex& a = p.vertices[p.indices[hit.first_index]];
    const plan::WorldVertex& b = p.vertices[p.indices[hit.first_index + 1]];
    const plan::WorldVertex& c = p.vertices[p.indices[hit.first_index + 2]];
    const double w0 = 1.0 - hit.b1 - hit.b2;
    const glm::dvec4 color = glm::dvec4(p.base_color_factor) *
                             (w0 * glm::dvec4(a.color) + hit.b1 * glm::dvec4(b.color) + hit.b2 * glm::dvec4(c.color));
    const glm::dvec3 face = glm::cross(glm::dvec3(b.position - a.position), glm::dvec3(c.position - a.position));
    const bool front = glm::dot(face, hit.direction) < 0.0;
    glm::dvec3 n;
    if (p.has_normals) {
        n = glm::normalize(w0 * glm::dvec3(a.normal) + hit.b1 * glm::dvec3(b.normal) + hit.b2 * glm::dvec3(c.normal));
        if (p.double_sided && !front) {
            n = -n;
        }
    } else {
        n = glm::normalize(front ? face : -face); // facing the viewer, as cross(dFdx, dFdy)
    }
    const glm::dvec3 to_light = glm::normalize(glm::dvec3(lighting.to_light));
    const double light = lighting.ambient + lighting.diffuse * std::max(glm::dot(n, to_light), 0.0);
    image::Rgba out{0, 0, 0, 255};
    for (int i = 0; i < 3; ++i) {
        out[static_cast<std::size_t>(i)] = to_unorm8(linear_to_srgb(std::clamp(color[i] * light, 0.0, 1.0)));
    }
    return out;
}

} // namespace

image::Image ray_cast_non_affine(const plan::WorldGeometry& geometry, const frustum::NonAffineFrustum<float>& frustum,
                                 const render::Lighting& lighting, const glm::vec4& clear_color, int width_px,
                                 int height_px) {
    const image::Rgba clear{to_unorm8(clear_color.r), to_unorm8(clear_color.g), to_unorm8(clear_color.b), 255};
    image::Image out = image::make_image(width_px, height_px, clear);
    const Caster caster(geometry, frustum);
    for (int y = 0; y < height_px; ++y) {
        for (int x = 0; x < width_px; ++x) {
            glm::dvec3 anchor, direction;
            const double u = (x + 0.5) / width_px, v = (y + 0.5) / height_px;
            if (!caster.line(u, v, anchor, direction)) {
                continue;
            }
            const Hit hit = caster.cast(anchor, direction);
            if (hit.primitive) {
                image::set_pixel(out, x, y, shade(hit, lighting));
            }
        }
    }
    return out;
}

} // namespace reference
