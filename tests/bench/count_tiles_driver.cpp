// Driver for scripts/count-instructions.sh, batched part: runs one batched
// update of a G x G grid of a 1280 x 720 image `repeats` times on one fixed,
// valid camera (success path), so that the difference of two instruction
// counts under qemu divided by the difference of repeats is one call; the
// script divides by G * G for the count per tile. The baselines build the
// same tiles' matrices and invert each with glm::inverse, as bench_ops does.
//
//   count_tiles_driver <op> <G> <repeats>
//   op: crop_tiles crop_tiles_glm lens_tiles lens_tiles_glm fit_volume
// fit_volume (G ignored, use 1): one curved-mirror patch fit (paper §4.3,
// Newton with the analytic Hessian) in double, on a camera's frustum whose
// side normals are tilted by about 0.6 degrees (a curved patch's target),
// from the paper's start.
#include "count_case.hpp"
#include "reinvert.hpp"

#include <frustum/detail/lens_matrices.hpp>
#include <frustum/volume_approximation.hpp>

#include <cstdio>
#include <cstdlib>
#include <vector>

using bench::keep;

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: count_tiles_driver <op> <G> <repeats>\n");
        return 2;
    }
    const char* op = argv[1];
    const int g = std::atoi(argv[2]);
    const int repeats = std::atoi(argv[3]);
    const auto camera = bench::count_camera();
    if (!camera || g < 1) {
        std::fprintf(stderr, "count_tiles_driver: %s (G=%d)\n", camera ? "grid size must be >= 1" : camera.error().c_str(), g);
        return 1;
    }
    frustum::MatrixPair<float> pair = *camera;
    const bench::RawPair<float> raw = bench::raw(pair);
    const auto frame = frustum::near_plane_frame(pair);
    frustum::Lens<float> lens{glm::vec2(0.1f, -0.05f) * frame->half_height_m, 0.6f * frame->half_height_m, 1.5f};
    keep(pair);
    keep(lens);
    static const char* const ops[] = {"crop_tiles", "crop_tiles_glm", "lens_tiles", "lens_tiles_glm", "fit_volume"};
    const int which = bench::op_index(op, ops);
    if (which < 0) {
        std::fprintf(stderr, "count_tiles_driver: unknown op '%s'\n", op);
        return 2;
    }
    // Storage made once, before the counted calls (as a renderer keeps it).
    frustum::TileGrid<float> grid, layout;
    std::vector<frustum::Mat4<float>> matrices, inverses(static_cast<std::size_t>(g * g));
    std::vector<bench::RawPair<float>> raw_tiles(static_cast<std::size_t>(g * g));
    int failures = 0;
    failures += !frustum::crop_tiles(pair, 1280, 720, g, g, grid).ok();
    failures += !frustum::detail::lens_tile_matrices(pair, lens, 1280, 720, g, g, layout, matrices).ok();
    const auto repeat = [&](auto&& body) {
        for (int i = 0; i < repeats; ++i) {
            body();
            keep(pair);
        }
    };
    switch (which) {
    case 0: repeat([&] { failures += !frustum::crop_tiles(pair, 1280, 720, g, g, grid).ok(); keep(grid); }); break;
    case 1:
        repeat([&] {
            std::size_t t = 0;
            for (int r = 0; r < g; ++r) {
                const int y0 = r * 720 / g, y1 = (r + 1) * 720 / g;
                for (int c = 0; c < g; ++c) {
                    const int x0 = c * 1280 / g, x1 = (c + 1) * 1280 / g;
                    const frustum::CropRect<float> rect{float(x0), float(y0), float(x1 - x0), float(y1 - y0), 1280, 720};
                    raw_tiles[t++] = bench::crop_reinvert(raw, rect);
                }
            }
            keep(raw_tiles);
        });
        break;
    case 2: repeat([&] { failures += !frustum::lens_tiles(pair, lens, 1280, 720, g, g, grid).ok(); keep(grid); }); break;
    case 3:
        repeat([&] {
            failures += !frustum::detail::lens_tile_matrices(pair, lens, 1280, 720, g, g, layout, matrices).ok();
            for (std::size_t t = 0; t < matrices.size(); ++t) {
                inverses[t] = glm::inverse(matrices[t]);
            }
            keep(inverses);
        });
        break;
    }
    if (which == 4) {
        // The target: an off-axis camera's near corners and side planes, the
        // normals tilted (fixed offsets, no random state).
        const auto projection = frustum::off_axis(-0.3, 0.5, -0.2, 0.35, 0.5, std::optional<double>(40.0),
                                                  frustum::DepthRange::ZeroToOne);
        const auto view = frustum::look_at(glm::dvec3(1, 2, 5), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
        const auto camera = frustum::compose(*projection, *view);
        const auto p = frustum::planes(camera);
        const auto k = frustum::key_points(camera);
        glm::dvec3 c[4];
        for (int i = 0; i < 4; ++i) c[i] = glm::dvec3(frustum::to_point(k.corners[i], 1e-12));
        frustum::VolumeTarget<double> target;
        target.near_points = {c[1], c[0], c[3], c[2]};
        target.side_normals = {p.top.normal(), p.right.normal(), p.bottom.normal(), p.left.normal()};
        const glm::dvec3 tilt[4] = {{0.01, -0.004, 0.006}, {-0.007, 0.009, 0.002}, {0.003, 0.008, -0.01},
                                    {-0.009, -0.002, 0.005}};
        for (int i = 0; i < 4; ++i) target.side_normals[i] = glm::normalize(target.side_normals[i] + tilt[i]);
        target.near = p.near;
        keep(target);
        int steps = 0;
        repeat([&] {
            const auto fit = frustum::fit_volume(target, 30.0, frustum::DepthRange::ZeroToOne);
            failures += !fit.ok();
            steps = fit ? fit->iterations : -1;
            keep(fit);
        });
        std::fprintf(stderr, "fit_volume: %d Newton solves\n", steps);
    }
    if (failures != 0) {
        std::fprintf(stderr, "count_tiles_driver: %s refused the case (%d times): not the success path\n", op, failures);
        return 1;
    }
    return 0;
}
