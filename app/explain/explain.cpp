#include "explain.hpp"

#include <frustum/frustum.hpp>

#include <cstdio>
#include <sstream>

namespace explain {

namespace {

using frustum::DepthRange;
using Pair = frustum::MatrixPair<double>;

std::string vec(const glm::dvec4& v) {
    char text[128];
    std::snprintf(text, sizeof text, "(%9.4f, %9.4f, %9.4f, %9.4f)", v.x, v.y, v.z, v.w);
    return text;
}

void print_matrix(std::ostringstream& out, const char* title, const glm::dmat4& m) {
    out << "  " << title << " (rows):\n";
    for (int r = 0; r < 4; ++r) {
        out << "    " << vec(frustum::row(m, r)) << "\n";
    }
}

void print_planes(std::ostringstream& out, const Pair& pair) {
    const auto p = frustum::planes(pair);
    const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};
    const auto all = p.as_array();
    out << "  planes, normalized and inward-positive (§3.1, eq. 1):\n";
    for (int i = 0; i < 6; ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "%-7s", names[i]);
        out << "    " << name << (all[i] ? vec(all[i]->abcd) : "absent (infinite)") << "\n";
    }
}

void print_points(std::ostringstream& out, const Pair& pair) {
    const auto k = frustum::key_points(pair);
    const double tolerance = frustum::infinity_tolerance<double>();
    out << "  key points from the inverse (§3.2, eq. 7-8; w = 0: at infinity):\n";
    for (int i = 0; i < 8; ++i) {
        out << "    C" << (i + 1) << "  " << vec(frustum::to_point(k.corners[i], tolerance)) << "\n";
    }
    out << "    D   " << vec(frustum::to_point(k.center, tolerance)) << "\n";
    out << "    O   " << vec(frustum::to_point(k.eye, tolerance)) << "\n";
    out << "    O1  " << vec(frustum::to_point(k.vanishing_y, tolerance)) << "\n";
    out << "    O2  " << vec(frustum::to_point(k.vanishing_x, tolerance)) << "\n";
}

double identity_error(const Pair& pair) {
    const glm::dmat4 product = pair.matrix() * pair.inverse();
    double worst = 0.0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            worst = std::max(worst, std::abs(product[c][r] - (c == r ? 1.0 : 0.0)));
        }
    }
    return worst;
}

} // namespace

frustum::Result<std::string> walkthrough(const Options& o) {
    constexpr double degrees = 3.14159265358979323846 / 180.0;
    const auto projection = frustum::perspective(o.fovy_deg * degrees, o.aspect, o.near_m,
                                                 std::optional<double>(o.far_m), DepthRange::ZeroToOne);
    if (!projection) return projection.take_error();
    const auto view = frustum::look_at(glm::dvec3(0, 1.7, 6), glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0));
    if (!view) return view.take_error();
    const Pair camera = frustum::compose(*projection, *view);

    std::ostringstream out;
    out << "Camera: perspective fovy " << o.fovy_deg << " deg, aspect " << o.aspect << ", near " << o.near_m
        << " m, far " << o.far_m << " m, depth range zero_to_one, eye (0, 1.7, 6) looking at (0, 1, 0)\n";
    print_matrix(out, "M = P V", camera.matrix());
    print_matrix(out, "M^-1 (closed form, no inversion)", camera.inverse());
    out << "  max |M M^-1 - I| = " << identity_error(camera) << "\n";
    print_planes(out, camera);
    print_points(out, camera);
    out << "  §5.5 valid: " << (frustum::validate(camera).valid() ? "yes" : "no") << "\n\n";

    const auto p = frustum::planes(camera);
    const auto far_corner = frustum::to_point(frustum::key_points(camera).corners[4], 1e-12);
    const auto rebuilt = frustum::from_planes(frustum::SidePlanes<double>{p.left, p.right, p.bottom, p.top, p.near},
                                              glm::dvec3(far_corner), DepthRange::ZeroToOne);
    if (!rebuilt) return rebuilt.take_error();
    const double factor = rebuilt->matrix()[3][3] / camera.matrix()[3][3];
    double deviation = 0.0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            deviation = std::max(deviation, std::abs(rebuilt->matrix()[c][r] - factor * camera.matrix()[c][r]));
        }
    }
    out << "Rebuilt from its five planes + far corner C5 (§4.1): equals M up to the factor " << factor
        << " (max deviation " << deviation << ")\n";
    const auto grown = frustum::from_planes_volume_growth(
        frustum::SidePlanes<double>{p.left, p.right, p.bottom, p.top, p.near}, DepthRange::ZeroToOne);
    if (!grown) return grown.take_error();
    out << "Rebuilt by volume growth (§4.2, corrected stop): " << grown->iterations << " iteration(s), valid: "
        << (frustum::validate(grown->pair).valid() ? "yes" : "no") << "\n\n";

    const frustum::Plane<double> floor_mirror(0, 1, 0, 0);
    const auto mirrored = frustum::mirror(camera, floor_mirror);
    if (!mirrored) return mirrored.take_error();
    out << "Mirror in the floor y = 0 (§5.2: reflect, then the floor becomes the near plane):\n";
    print_planes(out, *mirrored);
    out << "  winding flipped: " << (mirrored->flips_winding() ? "yes" : "no")
        << ", max |M M^-1 - I| = " << identity_error(*mirrored) << " (inverse updated analytically)\n\n";

    const auto tile = frustum::crop(camera, frustum::CropRect<double>{640, 0, 640, 360, 1280, 720});
    if (!tile) return tile.take_error();
    out << "Crop to the bottom-right quarter of a 1280x720 image (§5.1, offset from the bottom-left):\n";
    out << "  near corners C1..C4:\n";
    const auto corners = frustum::key_points(*tile).corners;
    for (int i = 0; i < 4; ++i) {
        out << "    C" << (i + 1) << "  " << vec(frustum::to_point(corners[i], 1e-12)) << "\n";
    }
    out << "  max |M M^-1 - I| = " << identity_error(*tile) << "\n";
    return out.str();
}

} // namespace explain
