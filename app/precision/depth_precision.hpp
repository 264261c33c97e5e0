// Depth precision of a pair, from the pair alone (docs/depth-precision.md):
// how many metres along a view ray one representable step of the depth
// buffer spans, for 24-bit fixed-point and 32-bit float depth, in any of
// the three depth ranges, with and without an oblique near plane. Pure: no
// GL, no printing (frustum-depth-precision prints).
#pragma once

#include <frustum/depth_range.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace precision {

enum class Storage { Fixed24, Float32 }; // GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32F

// The window depth in [0, 1] (glDepthRangef(0, 1)) the pair writes for
// world point p: (z_clip / w - z_lo) / (z_hi - z_lo). Empty when p is
// behind the eye or outside the depth range (clipped).
std::optional<double> window_depth(const frustum::MatrixPair<double>& pair, const glm::dvec3& p);

// The distance from `window` to the next representable depth value above
// it: 1 / (2^24 - 1) for Fixed24, one float ulp of `window` for Float32.
double depth_step(Storage storage, double window);

// Metres per representable depth step at p along the ray from `eye`
// through p: depth_step / |d window / d s|, the derivative taken in closed
// form from rows 2 and 3 of the matrix. Empty when p is clipped.
std::optional<double> metres_per_step(const frustum::MatrixPair<double>& pair, Storage storage,
                                      const glm::dvec3& eye, const glm::dvec3& p);

struct Sample {
    std::string setup;       // "showcase mirror" or "random planes"
    double tilt_deg = 0;     // the oblique plane against the un-clipped near plane
    double distance_m = 0;   // from the (reflected) eye along the ray
    frustum::DepthRange range = frustum::DepthRange::ZeroToOne;
    Storage storage = Storage::Fixed24;
    std::optional<double> oblique_m; // metres per step with the oblique near plane (empty: clipped)
    std::optional<double> plain_m;   // the same frustum without it
    int planes = 1;                  // random planes: how many went into the medians
};

// The showcase's mirror: its reflection pair (frustum::mirror, cropped)
// against the reflected, cropped pair without the oblique plane, along the
// ray from the reflected eye through the mirror's centre, at distances
// past the mirror (from `beyond_m`).
frustum::Result<std::vector<Sample>> showcase_samples(const scene::Scene& scene, const std::vector<double>& beyond_m);

// A 60-degree, 16:9 perspective (near 0.1 m, far 100 m) clipped by planes
// through a point 0.5..2 m down its axis, tilted by each of `tilts_deg`
// in random directions (`planes` per tilt, fixed seed); medians over the
// planes, along the axis at `distances_m`.
std::vector<Sample> random_plane_samples(const std::vector<double>& tilts_deg, const std::vector<double>& distances_m,
                                         int planes);

inline constexpr frustum::DepthRange kRanges[] = {frustum::DepthRange::MinusOneToOne, frustum::DepthRange::ZeroToOne,
                                                  frustum::DepthRange::ReversedZeroToOne};
inline constexpr Storage kStorages[] = {Storage::Fixed24, Storage::Float32};

std::string to_string(Storage storage); // "24-bit fixed", "32-bit float"

} // namespace precision
