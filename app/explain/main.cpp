// frustum-explain [--fovy-deg D] [--aspect A] [--near N] [--far F]
// Prints a walkthrough of the frustum library on one camera.
#include "explain.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>

namespace {

void usage(std::FILE* to) {
    std::fputs("usage: frustum-explain [--fovy-deg D] [--aspect A] [--near N] [--far F]\n"
               "Prints one camera's matrix pair, planes (paper §3.1), key points (§3.2), its\n"
               "rebuild from planes (§4) and a mirror and a crop of it (§5).\n",
               to);
}

bool parse_number(const char* text, double& out) {
    char* end = nullptr;
    out = std::strtod(text, &end);
    return end != text && *end == '\0';
}

} // namespace

static int run_main(int argc, char** argv) {
    explain::Options options;
    for (int i = 1; i < argc; i += 2) { // each option is followed by its number
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            usage(stdout);
            return 0;
        }
        double* target = arg == "--fovy-deg" ? &options.fovy_deg
                         : arg == "--aspect" ? &options.aspect
                         : arg == "--near"   ? &options.near_m
                         : arg == "--far"    ? &options.far_m
                                             : nullptr;
        if (!target) {
            std::fprintf(stderr, "frustum-explain: unknown option '%s'\n", arg.c_str());
            usage(stderr);
            return 2;
        }
        if (i + 1 >= argc || !parse_number(argv[i + 1], *target)) {
            std::fprintf(stderr, "frustum-explain: %s expects a number, got '%s'\n", arg.c_str(),
                         i + 1 < argc ? argv[i + 1] : "nothing");
            return 2;
        }
    }
    const auto text = explain::walkthrough(options);
    if (!text) {
        std::fprintf(stderr, "frustum-explain: %s\n", text.error().c_str());
        return 1;
    }
    std::fputs(text->c_str(), stdout);
    return 0;
}

// No exception leaves main: an allocation failure is a one-line error, exit 1.
int main(int argc, char** argv) {
    try {
        return run_main(argc, argv);
    } catch (const std::bad_alloc&) {
        std::fputs("frustum-explain: out of memory while writing the walkthrough\n", stderr);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "frustum-explain: internal error: %s\n", error.what());
    }
    return 1;
}
