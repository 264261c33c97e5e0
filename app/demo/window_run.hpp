// The window command: scene file -> window + GL ES context -> the frame
// loop (input, camera, mirror, render, blit, swap) until the window closes
// or --frames is reached. Prints nothing.
#pragma once

#include <functional>
#include <string_view>

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
// An effect that cannot be drawn for the current scene or camera does not
// end the run: the previous effect stays on screen, the overlay says why,
// and `note` gets the same line (as does the mirror placement).
// `args`: the command line `request` was parsed from (args[0] "window"),
// what the control panel edits.
std::variant<WindowRun, Failure> run_window(const WindowRequest& request, const std::vector<std::string>& args,
                                            const std::function<void(std::string_view)>& note);

} // namespace demo
