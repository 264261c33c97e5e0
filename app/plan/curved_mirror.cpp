#include "plan/curved_mirror.hpp"

#include <frustum/detail/enum_names.hpp>
#include <frustum/from_planes.hpp>
#include <frustum/queries.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace plan {
namespace {

constexpr const char* kCreate = "plan::CurvedMirror::create(): ";
// The least objective a patch frustum may have (F = sum of four cos^2, 4 =
// exact): about 9 degrees between each side plane and its target. Below it
// the reflected volume is no frustum-like pyramid, e.g. one wider than 180
// degrees (the showcase's cap with sagitta 0.9 m as a single patch: F = 2.94).
constexpr double kMinObjective = 3.9;
// fit_volume()'s Newton solves per patch at most (measured: at most 12 on the
// showcase, sphere and cylinder, G = 1..32; docs/curved-mirror.md).
constexpr int kMaxFitIterations = 50;

glm::dvec3 to_d(const glm::vec3& v) { return glm::dvec3(v); }

// Reflection of the direction d about the unit normal n: d - 2 (d . n) n.
glm::dvec3 reflect_direction(const glm::dvec3& d, const glm::dvec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

// Where the planes t_a . (p - a) = 0 (a = 0, 1, 2) meet, if they do
// (the paper's start point intersect(T0, T1, T2)).
std::optional<glm::dvec3> intersect3(const std::array<glm::dvec3, 3>& normals, const std::array<glm::dvec3, 3>& points) {
    const glm::dvec3& a = normals[0];
    const glm::dvec3& b = normals[1];
    const glm::dvec3& c = normals[2];
    const double det = glm::dot(a, glm::cross(b, c));
    if (!(std::abs(det) > 1e-9)) {
        return std::nullopt;
    }
    const double da = glm::dot(a, points[0]), db = glm::dot(b, points[1]), dc = glm::dot(c, points[2]);
    return (da * glm::cross(b, c) + db * glm::cross(c, a) + dc * glm::cross(a, b)) / det;
}

// The pair itself when its far plane clips none of the corners of `bounds`
// that it could show (w > 0 and beyond the near plane), else the same side
// and near planes rebuilt (§4.1, frustum::from_planes) with the far plane
// through the corner that needs the farthest one, moved 1% further from
// O: a far plane through Q has K_n ~ (m3 . Q) / (N . Q) (eq. 12) and covers
// every point p with (m3 . p) / (N . p) >= that ratio. (fit_volume() puts
// its far point on the axis through the corners' centroid: for a strongly
// trapezoidal patch the far plane pivots about a line near the scene and
// no distance along that axis reaches past it.)
frustum::Result<frustum::MatrixPair<double>> covering_scene(const frustum::MatrixPair<double>& pair,
                                                            const frustum::Plane<double>& near,
                                                            const glm::dvec3& origin, const scene::Bounds& bounds) {
    const auto all = frustum::planes(pair);
    const glm::dvec4 m3 = frustum::row(pair.matrix(), 3);
    bool clipped = false;
    std::optional<glm::dvec3> farthest;
    double smallest_ratio = std::numeric_limits<double>::infinity();
    for (const glm::vec3& corner_f : scene::corners(bounds)) {
        const glm::dvec3 corner(corner_f);
        const double w = glm::dot(m3, glm::dvec4(corner, 1.0));
        const double beyond = near.distance(corner);
        if (!(w > 0.0 && beyond > 0.0)) {
            continue;
        }
        clipped = clipped || (all.far && !(all.far->distance(corner) > 0.0));
        if (w / beyond < smallest_ratio) {
            smallest_ratio = w / beyond;
            farthest = corner;
        }
    }
    if (!clipped) {
        return pair;
    }
    const frustum::SidePlanes<double> sides{all.left, all.right, all.bottom, all.top, all.near};
    return frustum::from_planes(sides, origin + 1.01 * (*farthest - origin), pair.depth());
}

// The eye in front of the tangent planes at the patch's four corners.
bool sees_front(const CurvedMirror& mirror, const glm::dvec3& eye, int grid, int i, int j) {
    for (int corner = 0; corner < 4; ++corner) {
        const CapPoint p = mirror.at(static_cast<double>(i + (corner & 1)) / grid,
                                     static_cast<double>(j + (corner >> 1)) / grid);
        if (!(glm::dot(p.normal, eye - p.position) > 0.0)) {
            return false;
        }
    }
    return true;
}

} // namespace

constexpr frustum::detail::EnumName<CapShape> kCapShapeNames[] = {{CapShape::Sphere, "sphere"},
                                                                   {CapShape::Cylinder, "cylinder"}};

std::string_view to_string(CapShape shape) {
    const char* name = frustum::detail::find_enum_name(kCapShapeNames, shape);
    return name ? name : "?";
}

std::optional<CapShape> parse_cap_shape(std::string_view text) {
    return frustum::detail::find_enum_value(kCapShapeNames, text);
}

frustum::Result<CurvedMirror> CurvedMirror::create(const scene::MirrorRect& footprint, CapShape shape,
                                                   double sagitta_m) {
    CurvedMirror m;
    m.footprint_ = footprint;
    m.shape_ = shape;
    const glm::dvec3 a1 = to_d(footprint.a1), a2 = to_d(footprint.a2);
    m.length1_ = glm::length(a1);
    m.length2_ = glm::length(a2);
    const glm::dvec3 normal = glm::cross(a1, a2);
    if (!(m.length1_ > 0.0) || !(glm::length(normal) > 1e-9 * m.length1_ * m.length2_) ||
        !std::isfinite(glm::length(normal))) {
        return frustum::Error{std::string(kCreate) + "the footprint's sides a1, a2 must span a rectangle"};
    }
    m.e1_ = a1 / m.length1_;
    m.e2_ = a2 / m.length2_;
    m.n_ = glm::normalize(normal);
    m.center_ = to_d(footprint.corner) + 0.5 * (a1 + a2);
    // d: the largest |rho| over the footprint (the rim the cap passes through).
    const double d = shape == CapShape::Sphere
                         ? 0.5 * std::max(glm::length(a1 + a2), glm::length(a1 - a2))
                         : 0.5 * glm::length(a1 - glm::dot(a1, m.e2_) * m.e2_);
    if (!(sagitta_m >= 0.0) || !(sagitta_m <= 0.5 * d)) {
        return frustum::Error{std::string(kCreate) + "sagitta must be in [0, " + std::to_string(0.5 * d) +
                              "] m (half the distance from the centre to the rim), got " + std::to_string(sagitta_m)};
    }
    m.sagitta_ = sagitta_m;
    m.k_ = 2.0 * sagitta_m / (d * d + sagitta_m * sagitta_m);
    return m;
}

glm::dvec3 CurvedMirror::offset(double u, double v) const {
    const glm::dvec3 x = (u - 0.5) * to_d(footprint_.a1) + (v - 0.5) * to_d(footprint_.a2);
    return shape_ == CapShape::Sphere ? x : x - glm::dot(x, e2_) * e2_; // the cylinder's axis runs along a2
}

CapPoint CurvedMirror::at(double u, double v) const {
    const glm::dvec3 footprint = to_d(footprint_.corner) + u * to_d(footprint_.a1) + v * to_d(footprint_.a2);
    const glm::dvec3 rho = offset(u, v);
    const double r2 = glm::dot(rho, rho);
    const double q = std::sqrt(std::max(0.0, 1.0 - k_ * k_ * r2));
    const double h = sagitta_ - k_ * r2 / (1.0 + q);
    return {footprint + h * n_, glm::normalize(n_ + (k_ / q) * rho)};
}

std::optional<CurvedMirror::Hit> CurvedMirror::intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                                         double t_min) const {
    // |w + t dir|^2 = R^2 (projected off the axis for the cylinder) with
    // w = o - C = v + R n, v = o - apex, multiplied by k = 1/R:
    //   A t^2 + 2 B t + C = 0, A = k |dp|^2, B = dp.n + k dp.vp, C = 2 vp.n + k |vp|^2,
    // which stays exact as k -> 0 (the plane through the apex).
    const glm::dvec3 apex = center_ + sagitta_ * n_;
    const auto project = [&](const glm::dvec3& x) {
        return shape_ == CapShape::Sphere ? x : x - glm::dot(x, e2_) * e2_;
    };
    const glm::dvec3 dp = project(direction), vp = project(origin - apex);
    const double a = k_ * glm::dot(dp, dp);
    const double b = glm::dot(dp, n_) + k_ * glm::dot(dp, vp);
    const double c = 2.0 * glm::dot(vp, n_) + k_ * glm::dot(vp, vp);
    const double discriminant = b * b - a * c;
    if (!(discriminant >= 0.0)) {
        return std::nullopt;
    }
    // The smaller root (entering the convex side), in the form that does not cancel.
    double t;
    if (b < 0.0) {
        t = c / (-b + std::sqrt(discriminant));
    } else if (a > 0.0) {
        t = (-b - std::sqrt(discriminant)) / a;
    } else {
        return std::nullopt;
    }
    if (!(t > t_min)) {
        return std::nullopt;
    }
    const glm::dvec3 p = origin + t * direction - to_d(footprint_.corner);
    const glm::dvec3 a1 = to_d(footprint_.a1), a2 = to_d(footprint_.a2);
    const glm::dvec3 b1 = glm::cross(a2, n_) / glm::dot(a1, glm::cross(a2, n_)); // dual basis: b1.a1 = 1, b1.a2 = 0
    const glm::dvec3 b2 = glm::cross(n_, a1) / glm::dot(a2, glm::cross(n_, a1));
    const glm::dvec2 uv(glm::dot(p, b1), glm::dot(p, b2));
    const double height = glm::dot(p + to_d(footprint_.corner) - center_, n_);
    if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0 || height < -1e-9 * (length1_ + length2_)) {
        return std::nullopt;
    }
    return Hit{t, uv};
}

frustum::VolumeTarget<double> patch_target(const CurvedMirror& mirror, const glm::dvec3& eye, int grid, int i, int j) {
    const double g = static_cast<double>(grid);
    const double u0 = i / g, u1 = (i + 1) / g, v0 = j / g, v1 = (j + 1) / g;
    const std::array<CapPoint, 4> corners{mirror.at(u1, v1), mirror.at(u0, v1), mirror.at(u0, v0), mirror.at(u1, v0)};
    std::array<glm::dvec3, 4> x{}, reflected{};
    glm::dvec3 centroid(0.0), mean_reflected(0.0);
    for (std::size_t k = 0; k < 4; ++k) {
        x[k] = corners[k].position;
        reflected[k] = reflect_direction(glm::normalize(x[k] - eye), corners[k].normal);
        centroid += 0.25 * x[k];
        mean_reflected += 0.25 * reflected[k];
    }
    // Near plane: the corners' best fit, positive on the eye's side.
    glm::dvec3 near_normal = glm::normalize(glm::cross(x[2] - x[0], x[3] - x[1]));
    if (glm::dot(near_normal, eye - centroid) < 0.0) {
        near_normal = -near_normal;
    }
    frustum::VolumeTarget<double> target;
    target.near = frustum::Plane<double>(glm::dvec4(near_normal, -glm::dot(near_normal, centroid)));
    for (std::size_t k = 0; k < 4; ++k) {
        target.near_points[k] = x[k] - target.near.distance(x[k]) * near_normal;
    }
    // A point inside the reflected volume, to orient the side planes.
    const double size = glm::length(x[2] - x[0]);
    const glm::dvec3 inside = centroid + size * glm::normalize(mean_reflected);
    for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t next = (k + 1) % 4;
        const glm::dvec3 edge = target.near_points[next] - target.near_points[k];
        glm::dvec3 t = glm::normalize(glm::cross(edge, reflected[k] + reflected[next]));
        if (glm::dot(t, inside - target.near_points[k]) < 0.0) {
            t = -t;
        }
        target.side_normals[k] = t;
    }
    return target;
}

frustum::Result<std::optional<CurvedPlan>> plan_curved_mirror(const CurvedMirror& mirror, const glm::dvec3& eye,
                                                              const scene::Bounds& bounds, int grid) {
    if (grid < 1 || grid > kMaxCurvedPatches) {
        return frustum::Error{"plan::plan_curved_mirror(): the patch grid must be 1.." +
                              std::to_string(kMaxCurvedPatches) + ", got " + std::to_string(grid)};
    }
    if (!(glm::dot(eye - mirror.base_center(), mirror.base_normal()) > 0.0)) {
        return std::optional<CurvedPlan>();
    }
    const double diagonal_m = std::max(glm::length(glm::dvec3(bounds.max - bounds.min)), 1.0);
    CurvedPlan plan;
    plan.grid = grid;
    plan.patches.resize(static_cast<std::size_t>(grid * grid));
    for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
            PatchFrustum& patch = plan.patches[static_cast<std::size_t>(j * grid + i)];
            patch.i = i;
            patch.j = j;
            if (!sees_front(mirror, eye, grid, i, j)) {
                patch.error = "patch (" + std::to_string(i) + ", " + std::to_string(j) + "): seen from behind";
                ++plan.failed;
                continue;
            }
            const auto target = patch_target(mirror, eye, grid, i, j);
            const frustum::Plane<double> near = target.near.normalized();
            const auto start = intersect3({target.side_normals[0], target.side_normals[1], target.side_normals[2]},
                                          {target.near_points[0], target.near_points[1], target.near_points[2]});
            patch.start_objective = start && near.distance(*start) < 0.0
                                        ? frustum::volume_objective(target, *start)
                                        : std::numeric_limits<double>::quiet_NaN();
            // Warm start: the fitted origin of the patch to the left, else of
            // the one below (neighbouring patches' origins lie close together;
            // fit_volume() keeps the paper's start when it is no worse).
            std::optional<glm::dvec3> warm;
            if (i > 0 && plan.patches[static_cast<std::size_t>(j * grid + i - 1)].pair) {
                warm = plan.patches[static_cast<std::size_t>(j * grid + i - 1)].origin;
            } else if (j > 0 && plan.patches[static_cast<std::size_t>((j - 1) * grid + i)].pair) {
                warm = plan.patches[static_cast<std::size_t>((j - 1) * grid + i)].origin;
            }
            auto fit = frustum::fit_volume(target, diagonal_m, frustum::DepthRange::ZeroToOne, kMaxFitIterations,
                                           1e-10, warm);
            if (fit) {
                patch.origin = fit->origin;
                patch.objective = fit->objective;
                patch.iterations = fit->iterations;
                if (!(fit->objective >= kMinObjective)) {
                    patch.error = "F = " + std::to_string(fit->objective) + " < " + std::to_string(kMinObjective) +
                                  ": the reflected volume is too wide for one frustum (use more patches)";
                } else if (auto covering = covering_scene(fit->pair, near, fit->origin, bounds); !covering) {
                    patch.error = "no far plane reaches past the scene: " + covering.error();
                } else {
                    patch.pair = covering->cast<float>();
                }
            } else {
                patch.error = fit.error();
            }
            if (!patch.pair) {
                patch.error = "patch (" + std::to_string(i) + ", " + std::to_string(j) + "): " + patch.error;
                ++plan.failed;
            }
        }
    }
    return std::optional<CurvedPlan>(std::move(plan));
}

} // namespace plan
