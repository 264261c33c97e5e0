#include "window/key_help.hpp"

#include <plan/number_text.hpp>

#include <iterator>

namespace window {

std::vector<KeyHelp> key_help() {
    const std::size_t count = std::size(plan::kAllEffects);
    const std::string effects = "1.." + std::to_string(count);
    std::string names;
    for (std::size_t i = 0; i < count; ++i) {
        names += (i ? ", " : "") + std::to_string(i + 1) + " " + std::string(plan::to_string(plan::kAllEffects[i]));
    }
    return {
        {effects, "effect: " + names},
        {"left drag, A D W S", "orbit the camera around its target"},
        {"right drag, Shift+A D W S", "pan (Shift + left drag too)"},
        {"wheel, Q E", "zoom in / out"},
        {"R", "camera back to the scene's camera"},
        {"Left Right", "turn the mirror about the vertical"},
        {"Up Down", "tilt the mirror"},
        {"Shift+Left Right", "slide the mirror sideways"},
        {"Shift+Up Down", "move the mirror forward / back"},
        {"M", "mirror back to where the scene put it"},
        {"O", "mirror camera: oblique, rectangle, reflect_only"},
        {"+ -", "more / fewer tiles"},
        {"[ ]", "lens power down / up (lens effect)"},
        {", .", "recursion depth down / up, 0..8 (recursion effect)"},
        {"Z X, C V", "left, right facing mirror out / in (recursion effect)"},
        {"Shift+Z X, C V", "turn the left, right facing mirror (recursion effect)"},
        {"F", "frustum view inset on / off"},
        {"P", "control panel on / off (options, mirror placement, numbers)"},
        {"H", "this help on / off"},
        {"Esc", "quit"},
    };
}

std::vector<std::string> help_lines(const ViewerState& state) {
    std::vector<std::string> lines;
    lines.push_back("effect " + std::string(plan::to_string(state.effect)) + "   tiles " +
                    std::to_string(state.tile_columns) + "x" + std::to_string(state.tile_rows) + "   mirror camera " +
                    std::string(plan::to_string(state.mirror_method)) + "   lens power " +
                    plan::number_text(state.lens_power) + "   depth " + std::to_string(state.recursion_depth) +
                    (state.orbit ? "   camera: orbit" : "   camera: scene"));
    lines.emplace_back();
    for (const KeyHelp& entry : key_help()) {
        lines.push_back(entry.keys + "\t" + entry.action);
    }
    return lines;
}

std::string state_line(const ViewerState& state) {
    const auto degrees = [](float rad) { return plan::number_text(rad * 57.29577951308232f); };
    const auto on = [](bool value) { return value ? std::string("on") : std::string("off"); };
    std::string line = "effect=" + std::string(plan::to_string(state.effect));
    if (state.orbit) {
        const glm::vec3 t = state.orbit->target;
        line += " orbit=" + degrees(state.orbit->yaw_rad) + "," + degrees(state.orbit->pitch_rad) + " pan=" +
                plan::number_text(t.x) + "," + plan::number_text(t.y) + "," + plan::number_text(t.z) +
                " zoom=" + plan::number_text(state.orbit->distance_m);
    } else {
        line += " orbit=scene pan=scene zoom=scene";
    }
    line += " mirror.turn=" + degrees(state.mirror.turn_rad) + " mirror.tilt=" + degrees(state.mirror.tilt_rad) +
            " mirror.slide=" + plan::number_text(state.mirror.slide_m) +
            " mirror.push=" + plan::number_text(state.mirror.push_m);
    line += " mirror-camera=" + std::string(plan::to_string(state.mirror_method)) +
            " tiles=" + std::to_string(state.tile_columns) + "x" + std::to_string(state.tile_rows) +
            " lens-power=" + plan::number_text(state.lens_power) + " depth=" + std::to_string(state.recursion_depth);
    const char* sides[] = {"left", "right"};
    for (std::size_t i = 0; i < 2; ++i) {
        const plan::LinkMove move = i < state.link_moves.size() ? state.link_moves[i] : plan::LinkMove{};
        line += std::string(" ") + sides[i] + ".push=" + plan::number_text(move.push_m);
    }
    for (std::size_t i = 0; i < 2; ++i) {
        const plan::LinkMove move = i < state.link_moves.size() ? state.link_moves[i] : plan::LinkMove{};
        line += std::string(" ") + sides[i] + ".turn=" + degrees(move.turn_rad);
    }
    line += " inset=" + on(state.show_inset) + " panel=" + on(state.show_panel) + " help=" + on(state.show_help);
    return line;
}

} // namespace window
