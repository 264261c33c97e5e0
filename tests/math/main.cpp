// The math suite's entry point: doctest's own main (filters, -s, -d, ...).
// Everything here is pure math (frustum/ + GLM), no GL context needed.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
