// doctest entry point for the "window" suite: the window's camera, mirror
// moves, controls and text layout (pure), render_into / move_mirror on an
// offscreen context, and `frustum-demo window` itself under xvfb-run
// (skipped with a message when xvfb-run is not installed).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
