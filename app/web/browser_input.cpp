#include "web/browser_input.hpp"

#include <emscripten/html5.h>

#include <cctype>
#include <cmath>
#include <memory>
#include <utility>

namespace web {
namespace {

struct Listener {
    EventSink sink;
    std::optional<double> pinch_px; // distance between two touching fingers
};

gl::Modifiers modifiers(EM_BOOL shift, EM_BOOL control, EM_BOOL alt) {
    return gl::Modifiers{shift != 0, control != 0, alt != 0};
}

EM_BOOL on_mouse_button(int type, const EmscriptenMouseEvent* e, void* data) {
    auto& listener = *static_cast<Listener*>(data);
    gl::MouseButtonChanged changed;
    changed.button = e->button == 0 ? gl::MouseButton::Left : e->button == 1 ? gl::MouseButton::Middle
                                                                              : gl::MouseButton::Right;
    changed.pressed = type == EMSCRIPTEN_EVENT_MOUSEDOWN;
    changed.mods = modifiers(e->shiftKey, e->ctrlKey, e->altKey);
    if (changed.pressed) {
        // Where the drag starts (a release is heard on the whole document,
        // whose coordinates are not the canvas's).
        listener.sink(gl::CursorMoved{static_cast<double>(e->targetX), static_cast<double>(e->targetY)});
    }
    listener.sink(changed);
    return EM_TRUE;
}

EM_BOOL on_mouse_move(int, const EmscriptenMouseEvent* e, void* data) {
    static_cast<Listener*>(data)->sink(gl::CursorMoved{static_cast<double>(e->targetX), static_cast<double>(e->targetY)});
    return EM_TRUE;
}

EM_BOOL on_wheel(int, const EmscriptenWheelEvent* e, void* data) {
    // One wheel notch is 1 in GLFW; browsers report ~100 px, 3 lines or 1 page.
    const double per_notch = e->deltaMode == DOM_DELTA_PIXEL ? 100.0 : e->deltaMode == DOM_DELTA_LINE ? 3.0 : 1.0;
    // DOM: positive deltaY scrolls down (towards the user), GLFW: positive dy is away.
    static_cast<Listener*>(data)->sink(gl::Scrolled{e->deltaX / per_notch, -e->deltaY / per_notch});
    return EM_TRUE;
}

EM_BOOL on_touch(int type, const EmscriptenTouchEvent* e, void* data) {
    auto& listener = *static_cast<Listener*>(data);
    const EmscriptenTouchPoint* down[2] = {nullptr, nullptr};
    int count = 0;
    for (int i = 0; i < e->numTouches; ++i) {
        const bool lifted = (type == EMSCRIPTEN_EVENT_TOUCHEND || type == EMSCRIPTEN_EVENT_TOUCHCANCEL) &&
                            e->touches[i].isChanged;
        if (!lifted && count < 2) {
            down[count++] = &e->touches[i];
        }
    }
    if (count == 2) {
        // Pinch: the finger distance doubling = two wheel notches towards the scene.
        const double distance_px = std::hypot(static_cast<double>(down[0]->targetX - down[1]->targetX),
                                              static_cast<double>(down[0]->targetY - down[1]->targetY));
        listener.sink(gl::MouseButtonChanged{gl::MouseButton::Left, false, {}});
        if (listener.pinch_px && *listener.pinch_px > 0.0 && distance_px > 0.0) {
            listener.sink(gl::Scrolled{0.0, 2.0 * std::log2(distance_px / *listener.pinch_px)});
        }
        listener.pinch_px = distance_px;
        return EM_TRUE;
    }
    listener.pinch_px.reset();
    if (count == 1) {
        listener.sink(gl::CursorMoved{static_cast<double>(down[0]->targetX), static_cast<double>(down[0]->targetY)});
        if (type == EMSCRIPTEN_EVENT_TOUCHSTART || type == EMSCRIPTEN_EVENT_TOUCHEND) {
            listener.sink(gl::MouseButtonChanged{gl::MouseButton::Left, true, {}});
        }
    } else {
        listener.sink(gl::MouseButtonChanged{gl::MouseButton::Left, false, {}});
    }
    return EM_TRUE;
}

EM_BOOL on_key(int, const EmscriptenKeyboardEvent* e, void* data) {
    auto press = key_from_browser(e->key, e->shiftKey != 0, e->ctrlKey != 0, e->altKey != 0, e->repeat != 0);
    if (!press || press->mods.control || press->mods.alt) {
        return EM_FALSE; // the browser's own shortcuts keep working
    }
    static_cast<Listener*>(data)->sink(*press);
    return EM_TRUE;
}

frustum::Status check(EMSCRIPTEN_RESULT result, const char* what, const std::string& target) {
    if (result != EMSCRIPTEN_RESULT_SUCCESS && result != EMSCRIPTEN_RESULT_DEFERRED) {
        return frustum::Error{std::string("web::listen(): ") + what + " on '" + target +
                              "' failed (emscripten error " + std::to_string(result) + ")"};
    }
    return {};
}

} // namespace

std::optional<gl::KeyPressed> key_from_browser(const std::string& key, bool shift, bool control, bool alt,
                                               bool repeat) {
    gl::KeyPressed press;
    press.mods = gl::Modifiers{shift, control, alt};
    press.repeat = repeat;
    static const std::pair<const char*, gl::Key> named[] = {
        {"Escape", gl::Key::Escape}, {"ArrowLeft", gl::Key::Left},     {"ArrowRight", gl::Key::Right},
        {"ArrowUp", gl::Key::Up},    {"ArrowDown", gl::Key::Down},     {"PageUp", gl::Key::PageUp},
        {"PageDown", gl::Key::PageDown}, {"Home", gl::Key::Home}};
    for (const auto& [name, value] : named) {
        if (key == name) {
            press.key = value;
            return press;
        }
    }
    if (key.size() != 1 || !std::isprint(static_cast<unsigned char>(key[0]))) {
        return std::nullopt;
    }
    press.key = gl::Key::Character;
    press.character = static_cast<char>(std::toupper(static_cast<unsigned char>(key[0])));
    return press;
}

frustum::Status listen(const std::string& canvas, EventSink sink) {
    // Lives as long as the page: the browser calls back into it.
    auto* listener = new Listener{std::move(sink), std::nullopt};
    const char* target = canvas.c_str();
    if (auto s = check(emscripten_set_mousedown_callback(target, listener, EM_TRUE, on_mouse_button), "mousedown", canvas); !s) {
        return s;
    }
    // Releases and moves are followed over the whole page, so a drag may leave the canvas.
    if (auto s = check(emscripten_set_mouseup_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, listener, EM_TRUE, on_mouse_button),
                       "mouseup", "document");
        !s) {
        return s;
    }
    if (auto s = check(emscripten_set_mousemove_callback(target, listener, EM_TRUE, on_mouse_move), "mousemove", canvas); !s) {
        return s;
    }
    if (auto s = check(emscripten_set_wheel_callback(target, listener, EM_TRUE, on_wheel), "wheel", canvas); !s) {
        return s;
    }
    if (auto s = check(emscripten_set_touchstart_callback(target, listener, EM_TRUE, on_touch), "touchstart", canvas); !s) {
        return s;
    }
    if (auto s = check(emscripten_set_touchmove_callback(target, listener, EM_TRUE, on_touch), "touchmove", canvas); !s) {
        return s;
    }
    if (auto s = check(emscripten_set_touchend_callback(target, listener, EM_TRUE, on_touch), "touchend", canvas); !s) {
        return s;
    }
    if (auto s = check(emscripten_set_touchcancel_callback(target, listener, EM_TRUE, on_touch), "touchcancel", canvas);
        !s) {
        return s;
    }
    return check(emscripten_set_keydown_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, listener, EM_TRUE, on_key), "keydown",
                 "window");
}

} // namespace web
