// What every command of the app draws with, opened one way by frustum-demo
// (render, window, every report: demo/session.hpp) and the web page
// (web/viewer.hpp): the scene (within the budget) -> the camera -> the
// cameras -> the effect values resolved for the scene (the mirror placed)
// -> the GL context (the caller's) -> the function table -> the renderer.
// A command adds its own parts (the window's painter, a report's target)
// in a session of its own that derives from this one. No printing: notes
// go to a callback, errors come back as an OpenFailure.
#pragma once

#include "render/renderer.hpp"

#include <frustum/result.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <plan/camera.hpp>
#include <plan/effect_params.hpp>
#include <scene/load_gltf.hpp>
#include <scene/scene.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace render {

// The settings a session is opened from (frustum-demo's Settings derive from it).
struct SessionSettings {
    std::string scene_path;            // --scene; default: FRUSTUM_ASSETS_DIR/showcase.gltf
    std::optional<std::string> camera; // --camera NAME|INDEX; default "main", else camera 0
    int width_px = 640, height_px = 360; // --size: the image (window: its size in screen coordinates)
    bool verbose = false;              // --verbose: the GL context and its KHR_debug messages
    // --max-memory-mb (render: also bounds the run's output images),
    // --max-nodes, --max-depth, --max-drawn-vertices.
    scene::Budget budget;
};

// Why a session did not open: `usage` for what the command line asked
// (an unknown --camera, an explicit effect value the scene cannot take),
// else a runtime failure (the scene file, the context, the renderer).
struct OpenFailure {
    bool usage = false;
    std::string message;
};

using ContextMaker = std::function<frustum::Result<std::unique_ptr<gl::Context>>()>;

// How a command opens its session.
struct SessionHooks {
    bool cameras_at_size = true; // keep the cameras for a --size frame (the window and the page make their own)
    // An explicit effect value the scene cannot take (ResolvedEffects::refused)
    // fails the opening before any GL (render, the reports); the window refuses only its effect.
    bool refuse_explicit = true;
    ContextMaker make_context;                    // the context the renderer draws into
    std::function<void(std::string_view)> note;   // where the mirror went, far-plane and --verbose notes; may be empty
};

// The scene and its camera, as every session loads them (and the window's
// panel a new scene file): settings.scene_path within settings.budget
// (scene::load_gltf()'s error otherwise, a runtime failure), the camera
// settings.camera names (find_camera(); an unknown one is a usage failure).
struct LoadedScene {
    scene::Scene scene;
    int camera_index = -1;
};
std::variant<LoadedScene, OpenFailure> load_scene(const SessionSettings& settings);

// Members die in reverse: the renderer, then the table its objects point
// to, then the context; the scene outlives them all.
struct Session {
    scene::Scene scene;
    int camera_index = -1;
    std::optional<plan::Cameras> cameras; // at the settings' size (hooks.cameras_at_size)
    plan::ResolvedEffects effects;        // the effect values with what the scene derives (resolve_effects())
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<gl::Functions> fn; // stable address: GL objects point to it
    std::optional<Renderer> renderer;

    // The one way every command opens it: load_scene() -> the cameras at
    // the settings' size (one eye's with params.stereo) -> resolve_effects()
    // of `params` (the mirror placed where that camera sees it; a note says
    // where) -> hooks.make_context() -> its functions -> the renderer (which
    // draws the placed mirror). With settings.verbose, notes name the
    // scene's origin and the context.
    std::optional<OpenFailure> open(const SessionSettings& settings, const plan::EffectParams& params,
                                    const SessionHooks& hooks);
};

} // namespace render
