// doctest entry point for the "gl" suite: GL contexts, offscreen rendering
// and the image library. GL tests skip (with the backend's error) when a
// context cannot be created.
#include "../skips_main.hpp" // doctest's main, and a skip exits 77 (CTest: skipped)
