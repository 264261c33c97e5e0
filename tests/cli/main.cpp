// test_cli: frustum-vectors (and later command-line tools), label "cli".
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
