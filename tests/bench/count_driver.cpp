// Driver for scripts/count-instructions.sh: runs one operation `repeats` times
// on one fixed, valid case (success path), so that the difference of two
// instruction counts under qemu divided by the difference of repeats is the
// cost of one call. Also runs the baselines (new matrix + glm::inverse) and
// an empty loop, to subtract the loop itself.
//
//   count_driver <op> <repeats>
//   op: none crop reflect clip mirror glm_inverse crop_glm reflect_glm clip_glm mirror_glm
#include "count_case.hpp"
#include "reinvert.hpp"

#include <cstdio>
#include <cstdlib>

using bench::keep;
using frustum::DepthRange;

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: count_driver <op> <repeats>\n");
        return 2;
    }
    const char* op = argv[1];
    const int repeats = std::atoi(argv[2]);
    const auto camera = bench::count_camera();
    if (!camera) {
        std::fprintf(stderr, "count_driver: %s\n", camera.error().c_str());
        return 1;
    }
    const frustum::MatrixPair<float> pair = *camera;
    const bench::RawPair<float> raw = bench::raw(pair);
    // A mirror in front of the eye, facing it (the eye is at y = 1).
    frustum::Plane<float> plane(0.0f, 0.96f, 0.28f, 0.2f);
    frustum::Plane<float> clip_plane = plane.flipped(); // the eye on its negative side (flipped once, not per call)
    frustum::CropRect<float> rect{100, 50, 320, 180, 1280, 720};
    keep(plane);
    keep(rect);
    keep(clip_plane);
    static const char* const ops[] = {"none",        "crop",     "reflect",     "clip",     "mirror",
                                      "glm_inverse", "crop_glm", "reflect_glm", "clip_glm", "mirror_glm"};
    const int which = bench::op_index(op, ops);
    if (which < 0) {
        std::fprintf(stderr, "count_driver: unknown op '%s'\n", op);
        return 2;
    }
    // One loop per op (the name is looked up once, above): the loop costs
    // the same few instructions for every op, measured by "none".
    int failures = 0;
    const auto repeat = [&](auto&& body) {
        for (int i = 0; i < repeats; ++i) {
            body();
            keep(plane);
            keep(clip_plane);
        }
    };
    switch (which) {
    case 0: repeat([&] {}); break;
    case 1: repeat([&] { auto r = frustum::crop(pair, rect); failures += !r; keep(r); }); break;
    case 2: repeat([&] { auto r = frustum::reflect(pair, plane); failures += !r; keep(r); }); break;
    case 3: repeat([&] { auto r = frustum::clip_oblique(pair, clip_plane); failures += !r; keep(r); }); break;
    case 4: repeat([&] { auto r = frustum::mirror(pair, plane); failures += !r; keep(r); }); break;
    case 5: repeat([&] { auto r = glm::inverse(raw.matrix); keep(r); }); break;
    case 6: repeat([&] { auto r = bench::crop_reinvert(raw, rect); keep(r); }); break;
    case 7: repeat([&] { auto r = bench::reflect_reinvert(raw, plane); keep(r); }); break;
    case 8: repeat([&] { auto r = bench::clip_reinvert(raw, clip_plane, DepthRange::ZeroToOne); keep(r); }); break;
    case 9: repeat([&] { auto r = bench::mirror_reinvert(raw, plane, DepthRange::ZeroToOne); keep(r); }); break;
    }
    if (failures != 0) {
        std::fprintf(stderr, "count_driver: %s refused the case (%d times): not the success path\n", op, failures);
        return 1;
    }
    return 0;
}
