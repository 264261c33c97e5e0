// doctest entry point for test_poster_slow: the poster checks of issue 36
// too slow for the default gl suite (minutes on llvmpipe), built on demand
// (cmake --build build --target test_poster_slow), not run by `make test`.
#include "../../skips_main.hpp" // doctest's main, and a skip exits 77
