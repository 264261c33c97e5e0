// Accuracy of lens_tiles (paper §5.4) in float, against building each tile's
// matrix and inverting it with glm::inverse (detail::lens_tile_matrices),
// both measured against a double-precision reference: each tile built alone
// in double, §4's from_planes on its side planes (the same geometry: eye,
// warped corners, refraction plane, far plane through the farthest-reaching
// corner). Prints a Markdown table for docs/performance.md.
//
//   lens_accuracy [cameras per depth range, default 300]
//
// Per tile: the pair's residual max_ij |(M M^-1 - I)_ij| / (|M| |M^-1|)_ij
// (scale-free), and the corner error: max over the eight corners M^-1 (+-1,
// +-1, z, 1) of |corner - reference| / |reference - eye| (a projective pair
// is defined up to a factor, so points are compared, not entries). Tiles
// whose reference far corners lie behind the eye or past 1e4 far distances
// (extreme lenses, see lens.hpp) are compared on their near corners only.
#include "accuracy_measures.hpp"
#include "random_cases.hpp"

#include <frustum/detail/lens_matrices.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using frustum::DepthRange;
using frustum::Mat4;
using frustum::MatrixPair;
using frustum::Vec2;
using frustum::Vec3;
using frustum::Vec4;
using bench::pair_residual;

// Tile (x0..x1, y0..y1) px built alone in double (lens_tile_alone of
// tests/math/lens_tiles_test.cpp: the construction lens_tiles had before
// issue 34, independent of the library's grid code).
frustum::Result<MatrixPair<double>> reference_tile(const MatrixPair<double>& camera,
                                                   const frustum::Lens<double>& lens, int width_px, int height_px,
                                                   int x0, int x1, int y0, int y1) {
    using T = double;
    const auto frame = frustum::near_plane_frame(camera);
    const auto camera_planes = frustum::planes(camera);
    const T far_ratio = std::abs(camera_planes.far->distance(frame->eye)) /
                        std::abs(camera_planes.near.distance(frame->eye));
    frustum::NearPlaneFrame<T> relative = *frame;
    relative.center = frame->center - frame->eye;
    const auto moved = [&](int x_px, int y_px) {
        const Vec2<T> ndc(T(-1) + T(2) * T(x_px) / T(width_px), T(-1) + T(2) * T(y_px) / T(height_px));
        const Vec2<T> plane_m(ndc.x * frame->half_width_m, ndc.y * frame->half_height_m);
        return relative.point(frustum::lens_warp(plane_m, lens));
    };
    const auto side = [](const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& inside) {
        return frustum::Plane<T>::at(glm::normalize(glm::cross(a, b)), Vec3<T>(T(0))).facing(inside);
    };
    const Vec3<T> bl = moved(x0, y0), br = moved(x1, y0), tr = moved(x1, y1), tl = moved(x0, y1);
    const Vec3<T> inside = (bl + br + tr + tl) / T(4);
    const frustum::SidePlanes<T> sides{side(bl, tl, inside), side(br, tr, inside), side(bl, br, inside),
                                       side(tl, tr, inside),
                                       frustum::Plane<T>::at(camera_planes.near.normal(), relative.center)};
    const std::vector<Vec3<T>> far{bl * far_ratio, br * far_ratio, tr * far_ratio, tl * far_ratio};
    const auto pair = frustum::from_planes(sides, far, camera.depth());
    if (!pair) {
        return pair;
    }
    return frustum::compose(*pair, frustum::RigidTransform<T>::from_rotation_translation(glm::dmat3(1.0), -frame->eye));
}

// Max relative corner error of `inv` against the reference's corners
// (near corners only when `near_only`).
double corner_error(const Mat4<float>& inv, const glm::dmat4& reference, DepthRange depth, const glm::dvec3& eye,
                    bool near_only) {
    const glm::dmat4 id(inv);
    double worst = 0.0;
    const double zs[2] = {frustum::clip_z_near<double>(depth), frustum::clip_z_far<double>(depth)};
    for (int k = 0; k < (near_only ? 1 : 2); ++k) {
        for (int i = 0; i < 4; ++i) {
            const glm::dvec4 ndc(i == 1 || i == 2 ? 1.0 : -1.0, i >= 2 ? 1.0 : -1.0, zs[k], 1.0);
            const glm::dvec4 a = id * ndc, b = reference * ndc;
            const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
            worst = std::max(worst, glm::length(pa - pb) / glm::length(pb - eye));
        }
    }
    return worst;
}

struct Row {
    bench::Stats analytic, reinvert, analytic_residual, reinvert_residual;
    int tiles = 0, near_only = 0, rejected = 0, not_worse = 0;
};

std::string cell(bench::Stats& s) {
    char text[96];
    std::snprintf(text, sizeof text, "%.2e / %.2e / %.2e", s.mean(), s.quantile(0.99), s.quantile(1.0));
    return text;
}

const char* name(DepthRange depth) {
    switch (depth) {
    case DepthRange::ZeroToOne: return "zero_to_one";
    case DepthRange::MinusOneToOne: return "minus_one_to_one";
    case DepthRange::ReversedZeroToOne: return "reversed_zero_to_one";
    }
    return "?";
}

} // namespace

int main(int argc, char** argv) {
    const int cameras = argc > 1 ? std::atoi(argv[1]) : 300;
    const int width_px = 1280, height_px = 720;
    std::printf("| depth | power | G | tiles | corner error, analytic (mean / p99 / max) | corner error, matrix + "
                "glm::inverse | analytic <= glm | residual analytic | residual glm::inverse | near corners only | "
                "rejected |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (DepthRange depth : {DepthRange::ZeroToOne, DepthRange::MinusOneToOne, DepthRange::ReversedZeroToOne}) {
        const auto cases = bench::make_mirror_cases(cameras, depth, 34u);
        for (double power : {2.0, 1.5, 0.7}) {
            for (int g : {4, 16, 32}) {
                Row row;
                frustum::TileGrid<float> grid, layout;
                std::vector<Mat4<float>> matrices;
                for (const auto& c : cases) {
                    const MatrixPair<float> camera = c.camera.cast<float>();
                    const auto frame_d = frustum::near_plane_frame(c.camera);
                    if (!frame_d) continue;
                    const frustum::Lens<double> lens_d{glm::dvec2(0.1, -0.05) * frame_d->half_height_m,
                                                       0.6 * frame_d->half_height_m, power};
                    const frustum::Lens<float> lens{Vec2<float>(lens_d.center_m), float(lens_d.radius_m),
                                                    float(power)};
                    const bool ok = frustum::lens_tiles(camera, lens, width_px, height_px, g, g, grid).ok() &&
                                    frustum::detail::lens_tile_matrices(camera, lens, width_px, height_px, g, g,
                                                                        layout, matrices)
                                        .ok();
                    if (!ok) {
                        ++row.rejected;
                        continue;
                    }
                    const double far_m = frustum::far_distance(c.camera).value();
                    for (int r = 0; r < g; ++r) {
                        for (int col = 0; col < g; ++col) {
                            const std::size_t i = grid.index(col, r);
                            const auto ref = reference_tile(c.camera, lens_d, width_px, height_px, grid.x_px(col),
                                                            grid.x_px(col + 1), grid.y_px(r), grid.y_px(r + 1));
                            if (!ref) {
                                ++row.rejected;
                                continue;
                            }
                            const glm::dvec3 eye = frame_d->eye;
                            bool near_only = false;
                            for (int k = 0; k < 4; ++k) {
                                const double x = k == 1 || k == 2 ? 1.0 : -1.0, y = k >= 2 ? 1.0 : -1.0;
                                const glm::dvec4 n = ref->inverse() * glm::dvec4(x, y, frustum::clip_z_near<double>(depth), 1);
                                const glm::dvec4 f = ref->inverse() * glm::dvec4(x, y, frustum::clip_z_far<double>(depth), 1);
                                near_only = near_only || !(f.w * n.w > 0.0) ||
                                            glm::length(glm::dvec3(f) / f.w - eye) > 1e4 * far_m;
                            }
                            row.near_only += near_only ? 1 : 0;
                            const Mat4<float>& m = grid.matrices()[i];
                            const Mat4<float>& inv = grid.inverses()[i];
                            const Mat4<float> reinverted = glm::inverse(matrices[i]);
                            const double a = corner_error(inv, ref->inverse(), depth, eye, near_only);
                            const double b = corner_error(reinverted, ref->inverse(), depth, eye, near_only);
                            row.analytic.add(a);
                            row.reinvert.add(b);
                            row.not_worse += a <= b ? 1 : 0;
                            row.analytic_residual.add(pair_residual(m, inv));
                            row.reinvert_residual.add(pair_residual(matrices[i], reinverted));
                            ++row.tiles;
                        }
                    }
                }
                std::printf("| %s | %.1f | %d | %d | %s | %s | %.1f%% | %s | %s | %d | %d |\n", name(depth), power, g,
                            row.tiles, cell(row.analytic).c_str(), cell(row.reinvert).c_str(),
                            100.0 * row.not_worse / std::max(1, row.tiles), cell(row.analytic_residual).c_str(),
                            cell(row.reinvert_residual).c_str(), row.near_only, row.rejected);
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
