// The zlib level of streamed posters (issue 36, image::kStreamZlibLevel):
// the same decoded image written through image::PngStream at levels 1, 3
// and 6 (and any given), in bands of 256 rows as render_poster() delivers
// them; encoding Mpx/s per CPU second (best of 3) and file size, as a Markdown table.
//   poster_zlib IMAGE.png [LEVEL...]
// make bench-poster runs it on a 4096 x 4096 showcase render.
#include <image/png.hpp>
#include <image/png_stream.hpp>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: poster_zlib IMAGE.png [LEVEL...]\n");
        return 2;
    }
    const auto picture = image::read_png(argv[1]);
    if (!picture) {
        std::fprintf(stderr, "poster_zlib: %s\n", picture.error().c_str());
        return 1;
    }
    std::vector<int> levels;
    for (int i = 2; i < argc; ++i) {
        levels.push_back(std::atoi(argv[i]));
    }
    if (levels.empty()) {
        levels = {1, 3, 6};
    }
    const std::string out = std::string(argv[1]) + ".zlib-test.png";
    const double mpx = double(picture->width) * picture->height / 1e6;
    constexpr int kBandRows = 256;
    std::printf("%dx%d (%s)\n\n| zlib level | encode Mpx/s per CPU s (best of 3) | file MB |\n|---|---|---|\n", picture->width,
                picture->height, argv[1]);
    for (int level : levels) {
        double best_s = 1e30;
        for (int run = 0; run < 3; ++run) {
            const std::clock_t start = std::clock(); // CPU time: the machine may be shared
            auto stream = image::PngStream::open(out, picture->width, picture->height, level);
            if (!stream) {
                std::fprintf(stderr, "poster_zlib: %s\n", stream.error().c_str());
                return 1;
            }
            for (int top = 0; top < picture->height; top += kBandRows) {
                const int rows = std::min(kBandRows, picture->height - top);
                const auto first = picture->rgba.begin() + static_cast<long>(top) * picture->width * 4;
                image::Image band{picture->width, rows,
                                  std::vector<std::uint8_t>(first, first + static_cast<long>(rows) * picture->width * 4)};
                if (auto written = (*stream)->write_rows(band); !written) {
                    std::fprintf(stderr, "poster_zlib: %s\n", written.error().c_str());
                    return 1;
                }
            }
            if (auto finished = (*stream)->finish(); !finished) {
                std::fprintf(stderr, "poster_zlib: %s\n", finished.error().c_str());
                return 1;
            }
            best_s = std::min(best_s, double(std::clock() - start) / CLOCKS_PER_SEC);
        }
        struct stat status{};
        stat(out.c_str(), &status);
        std::printf("| %d | %.1f | %.2f |\n", level, mpx / best_s, status.st_size / 1048576.0);
    }
    std::remove(out.c_str());
    return 0;
}
