// test_cli: frustum-vectors (and later command-line tools), label "cli".
#include "../skips_main.hpp" // doctest's main; a skip (no GL for the poster tests) exits 77
