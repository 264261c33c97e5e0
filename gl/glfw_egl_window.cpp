#include "gl/glfw_egl_window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>
#include <utility>

namespace gl {
namespace {

constexpr const char* kCreate = "gl::GlfwEglWindow::create()";

// GLFW reports errors through one process-wide callback; keep the last one
// so that a failed call can say why.
std::string& last_glfw_error() {
    static std::string text;
    return text;
}

void remember_glfw_error(int code, const char* description) {
    last_glfw_error() = description != nullptr ? description : "GLFW error " + std::to_string(code);
}

// " (GLFW: <last error>)", or "" when GLFW said nothing.
std::string glfw_reason() {
    const std::string& text = last_glfw_error();
    return text.empty() ? std::string() : " (GLFW: " + text + ")";
}

// Why glfwInit failed, naming DISPLAY when it is the cause.
std::string init_failure() {
    const char* display = std::getenv("DISPLAY");
    const std::string glfw = last_glfw_error().empty() ? "" : "; GLFW: " + last_glfw_error();
    if (display == nullptr || *display == '\0') {
        return std::string(kCreate) + ": no display (DISPLAY is not set" + glfw + ")";
    }
    return std::string(kCreate) + ": cannot connect to the display (DISPLAY=" + display + glfw + ")";
}

Modifiers modifiers(int mods) {
    return {(mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_ALT) != 0};
}

// GLFW names printable keys by their US-layout character (GLFW_KEY_A == 'A').
KeyPressed translate_key(int key, int mods, bool repeat) {
    KeyPressed event;
    event.mods = modifiers(mods);
    event.repeat = repeat;
    switch (key) {
    case GLFW_KEY_ESCAPE: event.key = Key::Escape; return event;
    case GLFW_KEY_LEFT: event.key = Key::Left; return event;
    case GLFW_KEY_RIGHT: event.key = Key::Right; return event;
    case GLFW_KEY_UP: event.key = Key::Up; return event;
    case GLFW_KEY_DOWN: event.key = Key::Down; return event;
    case GLFW_KEY_PAGE_UP: event.key = Key::PageUp; return event;
    case GLFW_KEY_PAGE_DOWN: event.key = Key::PageDown; return event;
    case GLFW_KEY_HOME: event.key = Key::Home; return event;
    case GLFW_KEY_BACKSPACE: event.key = Key::Backspace; return event;
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER: event.key = Key::Enter; return event;
    case GLFW_KEY_KP_ADD: event.key = Key::Character; event.character = '+'; return event;
    case GLFW_KEY_KP_SUBTRACT: event.key = Key::Character; event.character = '-'; return event;
    default: break;
    }
    if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) {
        event.key = Key::Character;
        event.character = static_cast<char>('0' + (key - GLFW_KEY_KP_0));
    } else if (key >= GLFW_KEY_SPACE && key <= GLFW_KEY_GRAVE_ACCENT) {
        event.key = Key::Character;
        event.character = static_cast<char>(key);
    }
    return event;
}

} // namespace

// The GLFW callbacks; each finds its window through the user pointer.
struct GlfwCallbacks {
    static GlfwEglWindow& self(GLFWwindow* window) {
        return *static_cast<GlfwEglWindow*>(glfwGetWindowUserPointer(window));
    }
    static void key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
        if (action == GLFW_PRESS || action == GLFW_REPEAT) {
            self(window).pending_.emplace_back(translate_key(key, mods, action == GLFW_REPEAT));
        }
    }
    static void character(GLFWwindow* window, unsigned int codepoint) {
        self(window).pending_.emplace_back(TextEntered{codepoint});
    }
    static void mouse_button(GLFWwindow* window, int button, int action, int mods) {
        if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT && button != GLFW_MOUSE_BUTTON_MIDDLE) {
            return;
        }
        const MouseButton which = button == GLFW_MOUSE_BUTTON_LEFT    ? MouseButton::Left
                                  : button == GLFW_MOUSE_BUTTON_RIGHT ? MouseButton::Right
                                                                      : MouseButton::Middle;
        self(window).pending_.emplace_back(MouseButtonChanged{which, action == GLFW_PRESS, modifiers(mods)});
    }
    static void cursor(GLFWwindow* window, double x, double y) {
        self(window).pending_.emplace_back(CursorMoved{x, y});
    }
    static void scroll(GLFWwindow* window, double dx, double dy) {
        self(window).pending_.emplace_back(Scrolled{dx, dy});
    }
    static void framebuffer_size(GLFWwindow* window, int width, int height) {
        self(window).pending_.emplace_back(FramebufferResized{width, height});
    }
};

GlfwEglWindow::GlfwEglWindow(ContextOptions options, void* window)
    : Context(std::move(options)), window_(window) {}

GlfwEglWindow::~GlfwEglWindow() {
    glfwDestroyWindow(static_cast<GLFWwindow*>(window_));
}

frustum::Result<std::unique_ptr<GlfwEglWindow>> GlfwEglWindow::create(const WindowOptions& options) {
    const bool es = options.api == Api::Gles;
    // Core 4.3: "#version 300 es" through ARB_ES3_compatibility (the OSMesa backend's lowest too).
    const Version version = es ? options.context.gles_version.value_or(Version{3, 0})
                               : options.context.gl_version.value_or(Version{4, 3});
    const std::string api_version = std::string(to_string(options.api)) + " " + to_string(version);
    if (auto checked = check_requested_version(options.api, version, kCreate); !checked) {
        return checked.take_error();
    }
    if (options.width < 1 || options.height < 1) {
        return frustum::Error{std::string(kCreate) + ": width and height must be >= 1, got " +
                              std::to_string(options.width) + "x" + std::to_string(options.height)};
    }
    last_glfw_error().clear();
    glfwSetErrorCallback(remember_glfw_error);
    if (glfwInit() != GLFW_TRUE) {
        return frustum::Error{init_failure()};
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, es ? GLFW_OPENGL_ES_API : GLFW_OPENGL_API);
    if (!es) {
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    }
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, version.major);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, version.minor);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.context.debug ? GLFW_TRUE : GLFW_FALSE);
    // The frame is drawn offscreen and blitted here: no depth or stencil
    // needed, and an opaque window (no alpha for a compositor to blend).
    glfwWindowHint(GLFW_ALPHA_BITS, 0);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    GLFWwindow* window = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        return frustum::Error{std::string(kCreate) + ": glfwCreateWindow failed for " + api_version +
                              " through EGL" + glfw_reason()};
    }
    // From here the destructor cleans up on every early return.
    std::unique_ptr<GlfwEglWindow> self(new GlfwEglWindow(options.context, window));
    glfwSetWindowUserPointer(window, self.get());
    glfwSetKeyCallback(window, GlfwCallbacks::key);
    glfwSetCharCallback(window, GlfwCallbacks::character);
    glfwSetMouseButtonCallback(window, GlfwCallbacks::mouse_button);
    glfwSetCursorPosCallback(window, GlfwCallbacks::cursor);
    glfwSetScrollCallback(window, GlfwCallbacks::scroll);
    glfwSetFramebufferSizeCallback(window, GlfwCallbacks::framebuffer_size);
    if (auto ready = self->initialize(options.api, kCreate); !ready) {
        return frustum::Error{ready.error()};
    }
    glfwSwapInterval(options.vsync ? 1 : 0);
    return {std::move(self)};
}

frustum::Status GlfwEglWindow::make_current() {
    last_glfw_error().clear();
    glfwMakeContextCurrent(static_cast<GLFWwindow*>(window_));
    if (glfwGetCurrentContext() != window_) {
        return frustum::Error{"gl::GlfwEglWindow::make_current(): glfwMakeContextCurrent failed" + glfw_reason()};
    }
    return {};
}

Context::Proc GlfwEglWindow::get_proc_address(const char* name) const {
    return glfwGetProcAddress(name);
}

bool GlfwEglWindow::should_close() const {
    return glfwWindowShouldClose(static_cast<GLFWwindow*>(window_)) == GLFW_TRUE;
}

void GlfwEglWindow::request_close() {
    glfwSetWindowShouldClose(static_cast<GLFWwindow*>(window_), GLFW_TRUE);
}

std::vector<InputEvent> GlfwEglWindow::poll_events() {
    glfwPollEvents();
    return std::exchange(pending_, {});
}

std::vector<InputEvent> GlfwEglWindow::wait_events() {
    glfwWaitEvents();
    return std::exchange(pending_, {});
}

FramebufferSize GlfwEglWindow::framebuffer_size() const {
    FramebufferSize size;
    glfwGetFramebufferSize(static_cast<GLFWwindow*>(window_), &size.width_px, &size.height_px);
    return size;
}

void GlfwEglWindow::set_title(const std::string& title) {
    glfwSetWindowTitle(static_cast<GLFWwindow*>(window_), title.c_str());
}

void GlfwEglWindow::swap_buffers() {
    glfwSwapBuffers(static_cast<GLFWwindow*>(window_));
}

} // namespace gl
