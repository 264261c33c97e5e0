// Builds a small walkthrough of the library on one camera and writes it as
// text: matrix pair, planes (§3.1), key points (§3.2), a frustum rebuilt from
// its planes (§4), and the §5 operations. No printing here: main prints.
#pragma once

#include <frustum/result.hpp>

#include <string>

namespace explain {

struct Options {
    double fovy_deg = 60.0;
    double aspect = 16.0 / 9.0;
    double near_m = 0.1;
    double far_m = 100.0;
};

frustum::Result<std::string> walkthrough(const Options& options);

} // namespace explain
