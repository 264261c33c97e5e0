// doctest entry point for the "robustness" suite: bad input never crashes.
// Tables of bad inputs for the math library, the glTF loader and the
// command-line tools, each naming its input and the message it expects, and
// the fuzzers' regression inputs (tests/fuzz/regressions).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
