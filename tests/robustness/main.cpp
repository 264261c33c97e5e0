// doctest entry point for the "robustness" suite: bad input never crashes.
// Tables of bad inputs for the math library, the glTF loader and the
// command-line tools, each naming its input and the message it expects, and
// the fuzzers' regression inputs (tests/fuzz/regressions).
#include "../skips_main.hpp" // doctest's main, and a skip exits 77 (CTest: skipped)
