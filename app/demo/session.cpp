#include "demo/session.hpp"

#include <scene/load_gltf.hpp>

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

std::optional<Failure> load_session(Session& session, const Settings& settings, bool cameras_at_size) {
    auto loaded = load_scene(settings);
    if (auto* failure = std::get_if<Failure>(&loaded)) {
        return *failure;
    }
    session.scene = std::move(std::get<LoadedScene>(loaded).scene);
    session.camera_index = std::get<LoadedScene>(loaded).camera_index;
    if (cameras_at_size) {
        // Stereo: the cameras are made for one eye's half of the image.
        const int eye_width_px = settings.stereo ? settings.width_px / 2 : settings.width_px;
        auto cameras = render::make_cameras(session.scene, session.camera_index, eye_width_px, settings.height_px);
        if (!cameras) {
            return runtime(cameras.error());
        }
        session.cameras.emplace(std::move(*cameras));
    }
    return std::nullopt;
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

std::optional<Failure> start_gl(Session& session, const Settings& settings, const Reporter& reporter,
                                const ContextMaker& make) {
    auto context = make ? make() : make_context(settings, reporter);
    if (!context) {
        return runtime(context.error());
    }
    session.context = std::move(*context);
    if (settings.verbose) {
        reporter.note("context: " + gl::summary(session.context->describe()));
    }
    auto fn = gl::Functions::load(*session.context);
    if (!fn) {
        return runtime(fn.error());
    }
    session.fn = std::make_unique<gl::Functions>(*fn);
    auto renderer = render::Renderer::create(*session.context, *session.fn, session.scene);
    if (!renderer) {
        return runtime(renderer.error());
    }
    session.renderer.emplace(std::move(*renderer));
    return std::nullopt;
}

} // namespace demo
