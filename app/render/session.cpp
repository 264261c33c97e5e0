#include "render/session.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

namespace render {

std::variant<LoadedScene, OpenFailure> load_scene(const SessionSettings& settings) {
    scene::LoadOptions load_options;
    load_options.budget = settings.budget;
    auto scene = scene::load_gltf(settings.scene_path, load_options);
    if (!scene) {
        return OpenFailure{false, scene.error()};
    }
    auto camera_index = plan::find_camera(*scene, settings.camera);
    if (!camera_index) {
        return OpenFailure{true, camera_index.error()};
    }
    return LoadedScene{std::move(*scene), *camera_index};
}

std::optional<OpenFailure> Session::open(const SessionSettings& settings, const plan::EffectParams& params,
                                         const SessionHooks& hooks) {
    const auto note = [&hooks](const std::string& line) {
        if (hooks.note) {
            hooks.note(line);
        }
    };
    auto loaded = load_scene(settings);
    if (auto* failure = std::get_if<OpenFailure>(&loaded)) {
        return *failure;
    }
    scene = std::move(std::get<LoadedScene>(loaded).scene);
    camera_index = std::get<LoadedScene>(loaded).camera_index;
    if (settings.verbose && scene.origin_m != glm::dvec3(0.0)) {
        char origin[96]; // whole metres (scene.hpp)
        std::snprintf(origin, sizeof origin, "(%.0f, %.0f, %.0f)", scene.origin_m.x, scene.origin_m.y,
                      scene.origin_m.z);
        note(std::string("scene origin: ") + origin +
             " m in the file's coordinates; the positions below are relative to it");
    }
    // Stereo: the cameras are made for one eye's half of the image. The
    // window and the page make their own per framebuffer; these place its mirror.
    const int eye_width_px = std::max(1, params.stereo ? settings.width_px / 2 : settings.width_px);
    auto made = plan::make_cameras(scene, camera_index, eye_width_px, settings.height_px);
    if (!made) {
        return OpenFailure{false, made.error()};
    }
    if (made->far_note) {
        note(*made->far_note);
    }
    if (made->twin_note) {
        note(*made->twin_note);
    }
    // After the cameras (they frame the model), before the renderer (it draws the mirror placed here).
    effects = plan::resolve_effects(params, scene, &made->main.pair);
    if (hooks.cameras_at_size) {
        cameras.emplace(std::move(*made));
    }
    if (effects.placed) {
        note(*effects.placed);
    }
    if (effects.refused && hooks.refuse_explicit) {
        return OpenFailure{true, *effects.refused};
    }
    auto made_context = hooks.make_context();
    if (!made_context) {
        return OpenFailure{false, made_context.error()};
    }
    context = std::move(*made_context);
    if (settings.verbose) {
        note("context: " + gl::summary(context->describe()));
    }
    auto table = gl::Functions::load(*context);
    if (!table) {
        return OpenFailure{false, table.error()};
    }
    fn = std::make_unique<gl::Functions>(*table);
    auto made_renderer = Renderer::create(*context, *fn, scene);
    if (!made_renderer) {
        return OpenFailure{false, made_renderer.error()};
    }
    renderer.emplace(std::move(*made_renderer));
    return std::nullopt;
}

} // namespace render
