// The output folder, checked before any rendering so a run never fails
// after minutes of work because it cannot write its result.
#pragma once

#include <frustum/result.hpp>

#include <string>
#include <vector>

namespace demo {

// Creates `path` (and its parents) when missing, then creates and removes a
// probe file in it. Errors name the folder and the reason, e.g.
// "cannot write to output folder 'out': Permission denied".
frustum::Status prepare_output_dir(const std::string& path);

// The folders prepare_output_dir(path) would create: `path` and each missing
// parent, deepest first.
std::vector<std::string> missing_folders(const std::string& path);

// Removes each folder of `folders` (deepest first) that is empty, so a run
// that fails before writing anything leaves no new empty folder behind.
void remove_empty_folders(const std::vector<std::string>& folders);

} // namespace demo
