// Window-system input as plain values, so that code reacting to input needs
// no GLFW header (and can be tested without a window). GlfwEglWindow
// translates GLFW's callbacks into these, in the order they arrived.
#pragma once

#include <variant>

namespace gl {

enum class Key {
    Unknown,
    Character, // a printable key; KeyPressed::character tells which
    Escape,
    Left,
    Right,
    Up,
    Down,
    PageUp,
    PageDown,
    Home,
    Backspace, // text fields (the window panel's scene file)
    Enter,     // the main one or the keypad's
};

struct Modifiers {
    bool shift = false;
    bool control = false;
    bool alt = false;
};

// A key went down, or repeats while held. Printable keys are named by the
// character of their position on a US keyboard: 'A'..'Z' (upper case
// whatever Shift says: see mods), '0'..'9', '-', '=', '[', ']', ... The
// keypad's + and - arrive as '+' and '-'.
struct KeyPressed {
    Key key = Key::Unknown;
    char character = 0; // Key::Character only
    Modifiers mods;
    bool repeat = false;
};

enum class MouseButton { Left, Right, Middle };

struct MouseButtonChanged {
    MouseButton button = MouseButton::Left;
    bool pressed = false;
    Modifiers mods;
};

// Cursor position in screen coordinates, origin at the window's top-left
// corner (may differ from framebuffer pixels on high-DPI screens).
struct CursorMoved {
    double x = 0.0;
    double y = 0.0;
};

// Wheel or touchpad; positive dy = away from the user (zoom in).
struct Scrolled {
    double dx = 0.0;
    double dy = 0.0;
};

// A character typed (GLFW's character callback: after the keyboard layout
// and Shift), for text fields; the key itself also arrives as KeyPressed.
struct TextEntered {
    unsigned codepoint = 0; // Unicode
};

// The drawable size in pixels (what glViewport needs); 0 x 0 while minimized.
struct FramebufferResized {
    int width_px = 0;
    int height_px = 0;
};

using InputEvent = std::variant<KeyPressed, MouseButtonChanged, CursorMoved, Scrolled, FramebufferResized, TextEntered>;

} // namespace gl
