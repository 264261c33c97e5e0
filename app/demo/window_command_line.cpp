#include "demo/window_command_line.hpp"


namespace demo {

std::variant<HelpRequest, WindowRequest, Failure> parse_window_command_line(const std::vector<std::string>& args) {
    auto parsed = parse_options(kWindow, args);
    if (auto* request = std::get_if<Settings>(&parsed); request && request->screenshot && !request->frames) {
        return Failure{ExitStatus::UsageError, "--screenshot needs --frames N (the screenshot is frame N)"};
    }
    return parsed;
}

std::string window_help_text() {
    return "frustum-demo window: the effects live in a window (GLFW, OpenGL ES 3 or, with\n"
           "--context gl, desktop OpenGL core, through EGL), drawn by the same renderer as\n"
           "`frustum-demo render`.\n"
           "\n"
           "usage:\n"
           "  frustum-demo window [options]\n"
           "\n"
           "options:\n" +
           options_help(kWindow, false) + "effect options (the same as in render):\n" + options_help(kWindow, true) +
           "Unset effect parameters are derived from the scene and the camera of each\n"
           "frame (docs/any-scene.md). An effect that cannot be drawn from the current\n"
           "camera keeps the previous one on screen and says why in the overlay.\n"
           "\n"
           "Keys: H in the window lists them; see also docs/window.md.\n"
           "Needs a display (DISPLAY); without one use `frustum-demo render`, or run under\n"
           "xvfb-run. Exit status: 0 closed or done, 1 runtime failure, 2 usage error.\n";
}

} // namespace demo
