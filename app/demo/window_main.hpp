// `frustum-demo window ...`: parse, run, print. With main.cpp the only
// code of frustum-demo that prints.
#pragma once

#include <string>
#include <vector>

namespace demo {

// args[0] is "window"; returns the exit status.
int window_main(const std::vector<std::string>& args);

} // namespace demo
