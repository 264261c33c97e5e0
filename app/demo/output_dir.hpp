// The output folder, checked before any rendering so a run never fails
// after minutes of work because it cannot write its result.
#pragma once

#include <frustum/result.hpp>

#include <string>

namespace demo {

// Creates `path` (and its parents) when missing, then creates and removes a
// probe file in it. Errors name the folder and the reason, e.g.
// "cannot write to output folder 'out': Permission denied".
frustum::Status prepare_output_dir(const std::string& path);

} // namespace demo
