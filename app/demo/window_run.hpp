// The window command: scene file -> window + GL ES context -> the frame
// loop (input, camera, mirror, render, blit, swap) until the window closes
// or --frames is reached. Prints nothing.
#pragma once

#include "demo/failure.hpp"
#include "demo/window_command_line.hpp"

#include <string>
#include <variant>
#include <vector>

namespace demo {

struct WindowRun {
    int frames_drawn = 0;
    std::vector<std::string> written_paths; // the screenshot, when asked for
};

// Without a display the failure says so and points to `frustum-demo render`.
std::variant<WindowRun, Failure> run_window(const WindowRequest& request);

} // namespace demo
