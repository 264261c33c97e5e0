// Random cameras of the math suite: a deterministic generator
// (splitmix64) and well-conditioned cameras built through the library's
// own constructors.
#pragma once

#include "printers.hpp"
#include "support_basics.hpp"

namespace mtest {

// A small deterministic generator (splitmix64): identical sequences on
// every platform and standard library, unlike std::uniform_*_distribution.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t bits() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return double(bits() >> 11) * 0x1.0p-53; } // [0, 1)
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    int index(int n) { return int(bits() % std::uint64_t(n)); }
    bool coin() { return (bits() >> 63) != 0; }
    DepthRange depth() { return all_depth_ranges[index(3)]; }
    glm::dvec3 in_box(double half) { return {uniform(-half, half), uniform(-half, half), uniform(-half, half)}; }
    glm::dvec3 unit_vector() {
        for (;;) {
            const glm::dvec3 v = in_box(1.0);
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    }

private:
    std::uint64_t state_;
};

enum class Kind { Perspective, OffAxis, Orthographic };

inline const char* kind_name(Kind k) {
    return k == Kind::Perspective ? "perspective" : k == Kind::OffAxis ? "off_axis" : "orthographic";
}

// Everything needed to rebuild a camera, in double; `make<T>` builds it in
// T through the library's own constructors (so float tests exercise the
// float code paths, not a cast).
struct CameraSpec {
    Kind kind = Kind::Perspective;
    DepthRange depth = DepthRange::ZeroToOne;
    bool infinite = false; // perspective kinds only
    bool rotated = true;   // compose with a look_at view
    double fovy = 1, aspect = 1;
    double left = -1, right = 1, bottom = -1, top = 1;
    double near_m = 1, far_m = 10;
    glm::dvec3 eye{0}, target{0, 0, -1}, up{0, 1, 0};

    std::string text() const {
        std::ostringstream s;
        s << std::setprecision(17) << kind_name(kind) << " depth=" << frustum::to_string(depth)
          << (infinite ? " far=inf" : "") << " fovy=" << fovy << " aspect=" << aspect << " lrbt=(" << left << ", "
          << right << ", " << bottom << ", " << top << ") near=" << near_m << " far=" << far_m;
        if (rotated) s << " eye=" << vec_text(eye) << " target=" << vec_text(target) << " up=" << vec_text(up);
        return s.str();
    }
};

struct CameraOptions {
    bool perspective = true;
    bool off_axis = true;
    bool orthographic = true;
    bool infinite = true; // allow infinite far for the perspective kinds
    bool rotated = true;
};

// Well-conditioned by construction: fovy 30..110 degrees, aspect 0.5..2,
// near 0.1..2, far/near 5..200; off-axis windows shifted by up to 80% of
// their half size; orthographic boxes 1..20 wide, shifted by up to 5;
// eyes in [-20, 20]^3 looking 1..10 away, up at least ~12 degrees off the
// viewing direction.
inline CameraSpec random_camera(Random& rng, const CameraOptions& options = {}) {
    CameraSpec c;
    std::vector<Kind> kinds;
    if (options.perspective) kinds.push_back(Kind::Perspective);
    if (options.off_axis) kinds.push_back(Kind::OffAxis);
    if (options.orthographic) kinds.push_back(Kind::Orthographic);
    c.kind = kinds[std::size_t(rng.index(int(kinds.size())))];
    c.depth = rng.depth();
    c.fovy = rng.uniform(30, 110) * pi / 180;
    c.aspect = rng.uniform(0.5, 2);
    if (c.kind == Kind::Orthographic) {
        const double hw = rng.uniform(0.5, 10), hh = rng.uniform(0.5, 10);
        const double cx = rng.uniform(-5, 5), cy = rng.uniform(-5, 5);
        c.left = cx - hw, c.right = cx + hw, c.bottom = cy - hh, c.top = cy + hh;
        c.near_m = rng.uniform(-5, 5);
        c.far_m = c.near_m + rng.uniform(1, 100);
    } else {
        c.near_m = rng.uniform(0.1, 2);
        c.far_m = c.near_m * rng.uniform(5, 200);
        c.infinite = options.infinite && rng.index(3) == 0;
        if (c.kind == Kind::OffAxis) {
            const double hw = c.near_m * rng.uniform(0.3, 1.5), hh = c.near_m * rng.uniform(0.3, 1.5);
            const double cx = hw * rng.uniform(-0.8, 0.8), cy = hh * rng.uniform(-0.8, 0.8);
            c.left = cx - hw, c.right = cx + hw, c.bottom = cy - hh, c.top = cy + hh;
        }
    }
    c.rotated = options.rotated;
    if (c.rotated) {
        c.eye = rng.in_box(20);
        const glm::dvec3 dir = rng.unit_vector();
        c.target = c.eye + dir * rng.uniform(1, 10);
        do {
            c.up = rng.unit_vector();
        } while (glm::length(glm::cross(dir, c.up)) < 0.2);
    }
    return c;
}

template <class T>
frustum::Result<MatrixPair<T>> try_make(const CameraSpec& c) {
    using frustum::Result;
    std::optional<T> far;
    if (!c.infinite) far = T(c.far_m);
    Result<MatrixPair<T>> projection =
        c.kind == Kind::Perspective ? frustum::perspective<T>(T(c.fovy), T(c.aspect), T(c.near_m), far, c.depth)
        : c.kind == Kind::OffAxis
            ? frustum::off_axis<T>(T(c.left), T(c.right), T(c.bottom), T(c.top), T(c.near_m), far, c.depth)
            : frustum::orthographic<T>(T(c.left), T(c.right), T(c.bottom), T(c.top), T(c.near_m), T(c.far_m),
                                       c.depth);
    if (!projection || !c.rotated) return projection;
    const auto view = frustum::look_at<T>(Vec3<T>(c.eye), Vec3<T>(c.target), Vec3<T>(c.up));
    if (!view) return view.take_error();
    return frustum::compose(*projection, *view);
}

// Builds the camera; a failure is a test failure (the generator only makes
// valid cameras), reported with the camera.
template <class T>
MatrixPair<T> make(const CameraSpec& c) {
    auto pair = try_make<T>(c);
    INFO("camera: ", c.text());
    REQUIRE_MESSAGE(pair.ok(), pair.error());
    return *pair;
}

// Draws `count` random cameras from a generator seeded with `seed`, builds
// each in T (make<T>: a camera that fails to build fails the test) and runs
// check(rng, spec, pair) with the camera's text INFO'd; the generator is
// passed on for the draws a case makes after the camera's.
template <class T, class Check>
void for_each_random_camera(std::uint64_t seed, int count, Check check, const CameraOptions& options = {}) {
    Random rng(seed);
    for (int i = 0; i < count; ++i) {
        const CameraSpec c = random_camera(rng, options);
        const MatrixPair<T> pair = make<T>(c);
        INFO(c.text());
        check(rng, c, pair);
    }
}

} // namespace mtest
