// The render command: scene file -> cameras -> GL context -> one PNG per
// effect (+ a contact sheet). Reports through callbacks; prints nothing.
#pragma once

#include "demo/command_line.hpp"
#include "demo/failure.hpp"
#include "demo/session.hpp"

#include <frustum/result.hpp>
#include <gl/context.hpp>
#include <render/renderer.hpp>
#include <plan/stereo.hpp>
#include <scene/scene.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace demo {

struct RenderRun {
    std::vector<std::string> written_paths; // in the order written
    // One line per effect that could not be drawn ("nonaffine: ..."); the
    // others and the contact sheet are written all the same. Not empty:
    // main exits 1 after listing what was written.
    std::vector<std::string> failed_effects;
};

// What the current run is doing ("loading the scene", "rendering"), for
// main's "out of memory while ..." message when an allocation throws.
extern const char* g_activity;

// The --verbose line saying which clip depth range `path` gives on the
// renderer's context ("depth: [0, 1] clip range via clip control", ...).
std::string depth_summary(const render::Renderer& renderer, render::DepthPath path);

// The output folder is checked first, before the scene is read. A run that
// fails removes the folders it created while they are still empty.
std::variant<RenderRun, Failure> run_render(const RenderRequest& request, const Reporter& reporter);

} // namespace demo
