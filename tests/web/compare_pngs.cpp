// web_compare_pngs: the web test's image check (tests/web/run.sh).
//   web_compare_pngs BROWSER.png DESKTOP.png TOLERANCE MAX_FRACTION_OVER MAX_MEAN_ABS [DIFF.png]
// Passes (exit 0) when at most MAX_FRACTION_OVER of the pixels differ by more
// than TOLERANCE (0..255) in some channel and the mean channel difference is
// at most MAX_MEAN_ABS; prints the measured numbers either way, writes a
// visual diff when asked. Exit 1: over the tolerance; 2: bad arguments or files.
#include <image/compare.hpp>
#include <image/png.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

bool parse_number(const char* text, double& value) {
    char* end = nullptr;
    value = std::strtod(text, &end);
    return end != text && *end == '\0';
}

} // namespace

int main(int argc, char** argv) {
    double tolerance = 0.0, max_fraction = 0.0, max_mean = 0.0;
    if ((argc != 6 && argc != 7) || !parse_number(argv[3], tolerance) || !parse_number(argv[4], max_fraction) ||
        !parse_number(argv[5], max_mean)) {
        std::fprintf(stderr, "usage: web_compare_pngs A.png B.png TOLERANCE MAX_FRACTION_OVER MAX_MEAN_ABS [DIFF.png]\n");
        return 2;
    }
    auto a = image::read_png(argv[1]);
    auto b = image::read_png(argv[2]);
    if (!a || !b) {
        std::fprintf(stderr, "web_compare_pngs: %s\n", (!a ? a.error() : b.error()).c_str());
        return 2;
    }
    auto diff = image::compare(*a, *b, static_cast<int>(tolerance));
    if (!diff) {
        std::fprintf(stderr, "web_compare_pngs: %s\n", diff.error().c_str());
        return 2;
    }
    if (argc == 7) {
        auto visual = image::diff_image(*a, *b);
        if (!visual || !image::write_png(*visual, argv[6])) {
            std::fprintf(stderr, "web_compare_pngs: cannot write %s\n", argv[6]);
            return 2;
        }
    }
    const bool pass = diff->fraction_over() <= max_fraction && diff->mean_abs <= max_mean;
    std::printf("%s: %d of %d pixels (%.3f%%) differ by more than %d, max %d, mean %.3f; allowed %.3f%%, mean %.3f\n",
                pass ? "ok" : "FAIL", diff->pixels_over, diff->pixel_count, 100.0 * diff->fraction_over(),
                diff->tolerance, diff->max_abs, diff->mean_abs, 100.0 * max_fraction, max_mean);
    return pass ? 0 : 1;
}
