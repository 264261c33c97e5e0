// Shared helpers of the math suite, one header per job:
//   support_basics.hpp  names, depth ranges, pi, eps, MTEST_SANITIZED
//   printers.hpp        text of vectors, matrices, pairs (failing CHECKs show numbers)
//   tolerances.hpp      comparisons and tolerance helpers, with their reasoning
//   random_cameras.hpp  a deterministic generator of random, well-conditioned cameras
//   clip_space.hpp      clip-space points and planes, row literals
// Tests include this one.
#pragma once

#include "clip_space.hpp"
#include "printers.hpp"
#include "random_cameras.hpp"
#include "support_basics.hpp"
#include "tolerances.hpp"
