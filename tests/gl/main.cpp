// doctest entry point for the "gl" suite: GL contexts, offscreen rendering
// and the image library. GL tests skip (with the backend's error) when a
// context cannot be created.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
