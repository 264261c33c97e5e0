// What every frustum-demo command draws with, opened the same way by
// render, window and every report: the scene (within the --max-* budget)
// -> the camera (--camera) -> the GL context (offscreen: make_context's one
// fallback; the window: its own) -> the function table -> the renderer.
// The command adds its own parts (the window's painter, a report's target).
#pragma once

#include "demo/failure.hpp"
#include "demo/options.hpp"

#include <frustum/result.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <plan/camera.hpp>
#include <plan/effect_params.hpp>
#include <render/renderer.hpp>
#include <render/session.hpp>
#include <scene/scene.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <variant>

namespace demo {

struct Reporter {
    std::function<void(std::string_view)> progress; // "[2/4] mirror.png", multi-image runs only
    std::function<void(std::string_view)> note;     // backend fallback, --verbose context and KHR_debug lines
    // A long render's progress line ("mirror: 12/64 tiles, 3.4 Mpx/s, 41 s left"), at most once a
    // second, replaced in place; "" when done. Empty: not shown.
    std::function<void(std::string_view)> status = {};
};

using ContextMaker = render::ContextMaker;

// How a command opens its session.
struct OpenOptions {
    bool cameras_at_size = true; // the cameras for a --size frame (the window makes its own per framebuffer)
    // An explicit effect value the scene cannot take (plan::ResolvedEffects::refused)
    // is a usage error before any GL (render, the reports); the window refuses only its effect.
    bool refuse_explicit = true;
    ContextMaker make_context;   // empty: make_context() (offscreen, the one fallback)
};

// render::Session (render/session.hpp, which the web page opens too) with
// frustum-demo's settings, notes and exit statuses. A command's own session
// derives from it, so its GL objects die before the context.
struct Session : render::Session {
    // The one way every command opens it: render::Session::open() with the
    // settings' scene, camera, size and effect values, the context
    // how.make_context makes (empty: make_context()), notes to
    // reporter.note; a usage failure for an unknown --camera or an explicit
    // value the scene cannot take (how.refuse_explicit), else a runtime one.
    std::optional<Failure> open(const Settings& settings, const Reporter& reporter, const OpenOptions& how = {});
};

// --scene within the --max-* budget and its --camera, as every command
// loads them (and the window's panel a new scene file): render::load_scene(),
// an unreadable scene a runtime failure, an unknown --camera a usage error.
using LoadedScene = render::LoadedScene;
std::variant<LoadedScene, Failure> load_scene(const Settings& settings);

// The offscreen context: exactly --backend when given, otherwise EGL, then
// OSMesa with a note (when both fail, the error holds both reasons):
// gl::create_offscreen_context_with_fallback() with the note, the one
// fallback of the app and the GL tests. --verbose requests a debug context whose
// KHR_debug messages go to reporter.note.
frustum::Result<std::unique_ptr<gl::Context>> make_context(const Settings& settings, const Reporter& reporter);

// The context options --verbose asks for: a debug context, KHR_debug lines to `note`.
gl::ContextOptions context_options(const Settings& settings, const std::function<void(std::string_view)>& note);

} // namespace demo
