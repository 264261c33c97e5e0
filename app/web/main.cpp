// frustum-web: the showcase in a browser through WebGL 2 (docs/web.md).
// The page (shell.html) passes its URL fragment as arguments, e.g.
// "frustum-web.html#effect=mirror" -> "--effect mirror". This is the only
// file of the page that prints: errors go to the console and the page.
#include "web/browser_input.hpp"
#include "web/viewer.hpp"

#include <plan/effect.hpp>

#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace {

constexpr const char* kCanvas = "#canvas";
constexpr const char* kScenePath = "/scene/showcase.gltf"; // --embed-file, see CMakeLists.txt

std::unique_ptr<web::Viewer> g_viewer;
plan::Effect g_shown_effect = plan::Effect::Plain;

void report(const std::string& message) {
    std::fprintf(stderr, "frustum-web: %s\n", message.c_str());
    EM_ASM({ if (Module.frustumError) Module.frustumError(UTF8ToString($0)); }, message.c_str());
}

void mark_effect(plan::Effect effect) {
    g_shown_effect = effect;
    const std::string name(plan::to_string(effect));
    EM_ASM({ if (Module.frustumShowEffect) Module.frustumShowEffect(UTF8ToString($0)); }, name.c_str());
}

// Draws when something changed; false stops the frame loop after an error.
bool step() {
    int width_px = 0;
    int height_px = 0;
    emscripten_get_canvas_element_size(kCanvas, &width_px, &height_px);
    auto drew = g_viewer->draw_if_changed(width_px, height_px);
    if (!drew) {
        report(drew.error());
        return false;
    }
    if (*drew && g_viewer->effect() != g_shown_effect) {
        mark_effect(g_viewer->effect());
    }
    if (*drew) {
        EM_ASM({ if (Module.frustumDrew) Module.frustumDrew(); });
    }
    return true;
}

EM_BOOL on_animation_frame(double, void*) { return step() ? EM_TRUE : EM_FALSE; }

// "--effect NAME" is the only argument; anything else is refused by name.
bool parse_arguments(int argc, char** argv, web::ViewerOptions& options) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view name = argv[i];
        if (name != "--effect" || i + 1 >= argc) {
            report("unknown page argument '" + std::string(name) + "'; expected #effect=NAME");
            return false;
        }
        const std::string_view value = argv[++i];
        const auto effect = plan::parse_effect(value);
        if (!effect) {
            std::string names;
            for (plan::Effect known : plan::kAllEffects) {
                names += (names.empty() ? "" : ", ") + std::string(plan::to_string(known));
            }
            report("#effect must be one of " + names + ", got '" + std::string(value) + "'");
            return false;
        }
        options.effect = *effect;
    }
    return true;
}

} // namespace

// The page's effect buttons: the same as pressing 1..9 in the window.
extern "C" EMSCRIPTEN_KEEPALIVE void frustum_web_select_effect(int index) {
    if (g_viewer && index >= 0 && index < static_cast<int>(std::size(plan::kAllEffects))) {
        gl::KeyPressed press;
        press.key = gl::Key::Character;
        press.character = static_cast<char>('1' + index);
        g_viewer->push(press);
    }
}

int main(int argc, char** argv) {
    web::ViewerOptions options;
    options.scene_path = kScenePath;
    options.canvas = kCanvas;
    emscripten_get_canvas_element_size(kCanvas, &options.width_px, &options.height_px);
    options.note = [](std::string_view line) { std::printf("frustum-web: %.*s\n", static_cast<int>(line.size()), line.data()); };
    if (!parse_arguments(argc, argv, options)) {
        return 2;
    }
    auto viewer = web::Viewer::create(options);
    if (!viewer) {
        report(viewer.error());
        return 1;
    }
    g_viewer = std::move(*viewer);
    std::printf("frustum-web: %s\n", gl::summary(g_viewer->context_info()).c_str());
    for (int i = 0; i < static_cast<int>(std::size(plan::kAllEffects)); ++i) {
        const std::string name(plan::to_string(plan::kAllEffects[i]));
        EM_ASM({ if (Module.frustumAddEffect) Module.frustumAddEffect(UTF8ToString($0), $1); }, name.c_str(), i);
    }
    mark_effect(options.effect);
    if (auto listening = web::listen(kCanvas, [](const gl::InputEvent& event) { g_viewer->push(event); });
        !listening) {
        report(listening.error());
        return 1;
    }
    // The first frame now, so the page shows it as soon as it has loaded.
    if (!step()) {
        return 1;
    }
    emscripten_request_animation_frame_loop(on_animation_frame, nullptr);
    return 0;
}
