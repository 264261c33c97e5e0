#include "precision/depth_precision.hpp"

#include <plan/camera.hpp>
#include <plan/mirror_geometry.hpp>

#include <frustum/oblique_clip.hpp>
#include <frustum/projection.hpp>
#include <frustum/queries.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace precision {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec4 row(const glm::dmat4& m, int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); }

double z_lo(frustum::DepthRange range) {
    return std::min(frustum::clip_z_near<double>(range), frustum::clip_z_far<double>(range));
}
double z_span(frustum::DepthRange range) { return std::abs(frustum::clip_z_span<double>(range)); }

glm::dvec3 eye_of(const frustum::MatrixPair<double>& pair) {
    const glm::dvec4 eye = frustum::key_points(pair).eye;
    return glm::dvec3(eye) / eye.w;
}

std::optional<double> median(std::vector<double> values) {
    if (values.empty()) {
        return std::nullopt;
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One sample per range and storage for the pairs (ZeroToOne) at p.
void add_samples(std::vector<Sample>& out, const Sample& base, const frustum::MatrixPair<double>& oblique,
                 const frustum::MatrixPair<double>& plain, const glm::dvec3& eye, const glm::dvec3& p) {
    for (frustum::DepthRange range : kRanges) {
        for (Storage storage : kStorages) {
            Sample s = base;
            s.range = range;
            s.storage = storage;
            s.oblique_m = metres_per_step(oblique.with_depth_range(range), storage, eye, p);
            s.plain_m = metres_per_step(plain.with_depth_range(range), storage, eye, p);
            out.push_back(s);
        }
    }
}

} // namespace

std::string to_string(Storage storage) { return storage == Storage::Fixed24 ? "24-bit fixed" : "32-bit float"; }

std::optional<double> window_depth(const frustum::MatrixPair<double>& pair, const glm::dvec3& p) {
    const glm::dvec4 q(p, 1.0);
    const double w = glm::dot(row(pair.matrix(), 3), q);
    if (!(w > 0.0)) {
        return std::nullopt;
    }
    const double window = (glm::dot(row(pair.matrix(), 2), q) / w - z_lo(pair.depth())) / z_span(pair.depth());
    if (!(window >= 0.0 && window <= 1.0)) {
        return std::nullopt;
    }
    return window;
}

double depth_step(Storage storage, double window) {
    if (storage == Storage::Fixed24) {
        return 1.0 / 16777215.0;
    }
    const float stored = static_cast<float>(window);
    return static_cast<double>(std::nextafter(stored, 2.0f)) - static_cast<double>(stored);
}

std::optional<double> metres_per_step(const frustum::MatrixPair<double>& pair, Storage storage,
                                      const glm::dvec3& eye, const glm::dvec3& p) {
    const auto window = window_depth(pair, p);
    const double s = glm::length(p - eye);
    if (!window || !(s > 0.0)) {
        return std::nullopt;
    }
    // Along P(s) = E + s u: z(s) = (a + b s) / (c + e s), so
    // dz/ds = (b c - a e) / (c + e s)^2 (c = 0 when E is the eye).
    const glm::dvec3 u = (p - eye) / s;
    const glm::dvec4 m2 = row(pair.matrix(), 2), m3 = row(pair.matrix(), 3);
    const double a = glm::dot(m2, glm::dvec4(eye, 1.0)), b = glm::dot(m2, glm::dvec4(u, 0.0));
    const double c = glm::dot(m3, glm::dvec4(eye, 1.0)), e = glm::dot(m3, glm::dvec4(u, 0.0));
    const double w = c + e * s;
    const double dwindow_ds = std::abs((b * c - a * e) / (w * w)) / z_span(pair.depth());
    if (!(dwindow_ds > 0.0)) {
        return std::nullopt;
    }
    return depth_step(storage, *window) / dwindow_ds;
}

frustum::Result<std::vector<Sample>> showcase_samples(const scene::Scene& scene, const std::vector<double>& beyond_m) {
    constexpr int kWidthPx = 1280, kHeightPx = 720; // the crop moves x and y only, not depth
    if (!scene.mirror) {
        return frustum::Error{"precision::showcase_samples(): the scene has no mirror"};
    }
    auto index = plan::find_camera(scene, std::nullopt);
    if (!index) {
        return frustum::Error{index.error()};
    }
    auto cameras = plan::make_cameras(scene, *index, kWidthPx, kHeightPx);
    if (!cameras) {
        return frustum::Error{cameras.error()};
    }
    const auto reflection_for = [&](plan::MirrorMethod method) {
        return plan::plan_reflection(*scene.mirror, cameras->main.pair, kWidthPx, kHeightPx, method,
                                     scene.world_bounds);
    };
    auto oblique = reflection_for(plan::MirrorMethod::Oblique);
    auto plain = reflection_for(plan::MirrorMethod::ReflectOnly);
    if (!oblique || !plain) {
        return frustum::Error{!oblique ? oblique.error() : plain.error()};
    }
    if (!oblique->has_value() || !plain->has_value()) {
        return frustum::Error{"precision::showcase_samples(): the main camera does not see the mirror"};
    }
    const frustum::MatrixPair<double> oblique_pair = (*oblique)->pair.cast<double>();
    const frustum::MatrixPair<double> plain_pair = (*plain)->pair.cast<double>();
    const glm::dvec3 eye = eye_of(plain_pair);
    const scene::MirrorRect& m = *scene.mirror;
    const glm::dvec3 centre = glm::dvec3(m.corner) + 0.5 * glm::dvec3(m.a1) + 0.5 * glm::dvec3(m.a2);
    const glm::dvec3 ray = glm::normalize(centre - eye);
    const glm::dvec3 mirror_normal = glm::normalize(glm::cross(glm::dvec3(m.a1), glm::dvec3(m.a2)));
    const glm::dvec3 near_normal = frustum::planes(plain_pair).near.normalized().normal();
    Sample base;
    base.setup = "showcase mirror";
    base.tilt_deg = std::acos(std::min(1.0, std::abs(glm::dot(mirror_normal, near_normal)))) * 180.0 / kPi;
    std::vector<Sample> out;
    for (double beyond : beyond_m) {
        base.distance_m = glm::length(centre - eye) + beyond;
        add_samples(out, base, oblique_pair, plain_pair, eye, eye + base.distance_m * ray);
    }
    return out;
}

std::vector<Sample> random_plane_samples(const std::vector<double>& tilts_deg, const std::vector<double>& distances_m,
                                         int planes) {
    const auto camera = frustum::perspective<double>(kPi / 3.0, 16.0 / 9.0, 0.1, 100.0, frustum::DepthRange::ZeroToOne);
    std::mt19937 random(17);
    std::uniform_real_distribution<double> azimuth_rad(0.0, 2.0 * kPi), through_m(0.5, 2.0);
    const glm::dvec3 eye(0.0), axis(0.0, 0.0, -1.0);
    std::vector<Sample> out;
    for (double tilt : tilts_deg) {
        // Per distance, range and storage: the values over the planes.
        std::vector<std::vector<double>> oblique_values, plain_values;
        std::vector<Sample> rows;
        int used = 0;
        for (int i = 0; i < planes; ++i) {
            const double phi = azimuth_rad(random), d = through_m(random), t = tilt * kPi / 180.0;
            // Normal tilted by t from the axis (away from the eye: the eye on the negative side).
            const glm::dvec3 n(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), -std::cos(t));
            const frustum::Plane<double> plane(n.x, n.y, n.z, -glm::dot(n, d * axis));
            auto clipped = frustum::clip_oblique(*camera, plane);
            if (!clipped) {
                continue;
            }
            ++used;
            std::vector<Sample> one;
            for (double distance : distances_m) {
                Sample base;
                base.setup = "random planes";
                base.tilt_deg = tilt;
                base.distance_m = distance;
                add_samples(one, base, *clipped, *camera, eye, distance * axis);
            }
            if (rows.empty()) {
                rows = one;
                oblique_values.resize(one.size());
                plain_values.resize(one.size());
            }
            for (std::size_t k = 0; k < one.size(); ++k) {
                // A clipped point counts as infinitely coarse for the median.
                oblique_values[k].push_back(one[k].oblique_m.value_or(HUGE_VAL));
                if (one[k].plain_m) {
                    plain_values[k].push_back(*one[k].plain_m);
                }
            }
        }
        for (std::size_t k = 0; k < rows.size(); ++k) {
            rows[k].oblique_m = median(oblique_values[k]);
            if (rows[k].oblique_m && std::isinf(*rows[k].oblique_m)) {
                rows[k].oblique_m.reset();
            }
            rows[k].plain_m = median(plain_values[k]);
            rows[k].planes = used;
            out.push_back(rows[k]);
        }
    }
    return out;
}

} // namespace precision
