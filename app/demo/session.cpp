#include "demo/session.hpp"

#include <scene/load_gltf.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

namespace demo {

std::variant<LoadedScene, Failure> load_scene(const Settings& settings) {
    scene::LoadOptions load_options;
    load_options.budget = settings.budget;
    auto scene = scene::load_gltf(settings.scene_path, load_options);
    if (!scene) {
        return runtime(scene.error());
    }
    auto camera_index = render::find_camera(*scene, settings.camera);
    if (!camera_index) {
        return Failure{ExitStatus::UsageError, camera_index.error()};
    }
    return LoadedScene{std::move(*scene), *camera_index};
}

gl::ContextOptions context_options(const Settings& settings, const std::function<void(std::string_view)>& note) {
    gl::ContextOptions options;
    if (settings.verbose) {
        options.debug = true;
        options.debug_sink = [note](std::string_view line) { note(line); };
    }
    return options;
}

frustum::Result<std::unique_ptr<gl::Context>> make_context(const Settings& settings, const Reporter& reporter) {
    const gl::ContextOptions options = context_options(settings, reporter.note);
    if (settings.backend) {
        return gl::create_offscreen_context(*settings.backend, options);
    }
    return gl::create_offscreen_context_with_fallback(options, [&reporter](const std::string& egl_error) {
        reporter.note("note: no EGL context (" + egl_error + "); using OSMesa");
    });
}

std::optional<Failure> Session::open(const Settings& settings, const Reporter& reporter, const OpenOptions& how) {
    auto loaded = load_scene(settings);
    if (auto* failure = std::get_if<Failure>(&loaded)) {
        return *failure;
    }
    scene = std::move(std::get<LoadedScene>(loaded).scene);
    camera_index = std::get<LoadedScene>(loaded).camera_index;
    if (settings.verbose && scene.origin_m != glm::dvec3(0.0)) {
        char origin[96]; // whole metres (scene.hpp)
        std::snprintf(origin, sizeof origin, "(%.0f, %.0f, %.0f)", scene.origin_m.x, scene.origin_m.y,
                      scene.origin_m.z);
        reporter.note(std::string("scene origin: ") + origin +
                      " m in the file's coordinates; the positions below are relative to it");
    }
    // Stereo: the cameras are made for one eye's half of the image. The
    // window makes its own per framebuffer; these place its mirror.
    const int eye_width_px = std::max(1, settings.stereo ? settings.width_px / 2 : settings.width_px);
    auto made = render::make_cameras(scene, camera_index, eye_width_px, settings.height_px);
    if (!made) {
        return runtime(made.error());
    }
    if (made->far_note) {
        reporter.note(*made->far_note);
    }
    // After the cameras (they frame the model), before the renderer (it draws the mirror placed here).
    effects = render::resolve_effects(settings, scene, &made->main.pair);
    if (how.cameras_at_size) {
        cameras.emplace(std::move(*made));
    }
    if (effects.placed) {
        reporter.note(*effects.placed);
    }
    if (effects.refused && how.refuse_explicit) {
        return Failure{ExitStatus::UsageError, *effects.refused};
    }
    auto made_context = how.make_context ? how.make_context() : make_context(settings, reporter);
    if (!made_context) {
        return runtime(made_context.error());
    }
    context = std::move(*made_context);
    if (settings.verbose) {
        reporter.note("context: " + gl::summary(context->describe()));
    }
    auto table = gl::Functions::load(*context);
    if (!table) {
        return runtime(table.error());
    }
    fn = std::make_unique<gl::Functions>(*table);
    auto made_renderer = render::Renderer::create(*context, *fn, scene);
    if (!made_renderer) {
        return runtime(made_renderer.error());
    }
    renderer.emplace(std::move(*made_renderer));
    return std::nullopt;
}

} // namespace demo
