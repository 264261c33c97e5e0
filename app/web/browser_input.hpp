// Browser input -> gl::InputEvent, the values the desktop window's GLFW
// callbacks produce (gl/window_input.hpp), so window::Controls works
// unchanged: mouse buttons, moves and the wheel on the canvas, one-finger
// touch drags as a left-button drag, a two-finger pinch as the wheel, and
// the window's keys (1..7 effects, H help, F inset, R reset, W/A/S/D/Q/E
// camera, arrows mirror, ...) from the keyboard.
#pragma once

#include <gl/window_input.hpp>

#include <frustum/result.hpp>

#include <functional>
#include <optional>
#include <string>

namespace web {

using EventSink = std::function<void(const gl::InputEvent&)>;

// The key a browser KeyboardEvent.key names ("a", "ArrowLeft", "PageUp",
// "+", ...), as GLFW would report it; empty for keys the window ignores.
std::optional<gl::KeyPressed> key_from_browser(const std::string& key, bool shift, bool control, bool alt,
                                               bool repeat);

// Mouse, wheel and touch on the canvas `canvas` (CSS selector) and keys on
// the page go to `sink` from now on (which must live as long as the page).
// Errors name the listener emscripten refused.
frustum::Status listen(const std::string& canvas, EventSink sink);

} // namespace web
