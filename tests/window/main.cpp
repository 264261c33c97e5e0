// doctest entry point for the "window" suite: the window's camera, mirror
// moves, controls and text layout (pure), render_into / move_mirror on an
// offscreen context, and `frustum-demo window` itself under xvfb-run
// (skipped with a message when xvfb-run is not installed).
#include "../skips_main.hpp" // doctest's main, and a skip exits 77 (CTest: skipped)
