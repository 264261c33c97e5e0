// doctest main for the "scene" suite; a skipped check (tests/skips.hpp: the
// external corpus not configured) makes the run a skip (exit 77), not a pass.
#include "../skips_main.hpp"
