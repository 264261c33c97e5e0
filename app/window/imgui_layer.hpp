// Dear ImGui in the window: one ImGui context, its input fed from the
// window's gl::InputEvent values (no GLFW backend: the window already owns
// GLFW's callbacks), and its draw data painted with window::ImGuiPainter.
// The panel's widgets are the caller's, between begin_frame() and
// end_frame().
#pragma once

#include "window/imgui_painter.hpp"

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/window_input.hpp>

#include <memory>
#include <optional>
#include <vector>

struct ImGuiContext;

namespace window {

class ImGuiLayer {
public:
    // Makes the ImGui context (no ini file: every run starts the same) and
    // the painter. One layer at a time per process (ImGui's current context).
    static frustum::Result<std::unique_ptr<ImGuiLayer>> create(const gl::Functions& fn);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // Takes this frame's events and returns those the rest of the window
    // gets: every event but the mouse's while the pointer is over a panel
    // window (or a drag started there). A second press or release of a
    // button within one frame waits for the next frame, so a quick click
    // (press and release in one poll) still reaches ImGui as a click.
    // While an ImGui text field is edited, the keys and typed characters
    // are its own (Backspace, Enter, Left, Right, Home, Esc; each down for
    // one frame) and none passes.
    // `shown`: false = ImGui sees nothing and every event passes.
    std::vector<gl::InputEvent> feed(std::vector<gl::InputEvent> events, bool shown);

    // Starts an ImGui frame on a width_px x height_px framebuffer
    // (the window's size in screen coordinates: window_width x window_height).
    void begin_frame(int width_px, int height_px, double seconds_since_last);
    // Ends the frame and draws it over framebuffer 0.
    frustum::Status end_frame();

private:
    ImGuiLayer(ImGuiContext* context, ImGuiPainter painter);
    void apply(const gl::InputEvent& event);

    ImGuiContext* context_;
    ImGuiPainter painter_;
    std::vector<gl::InputEvent> waiting_; // mouse events for the next frames
    std::vector<gl::InputEvent> keys_waiting_; // a text field's keys for the next frames
    int width_px_ = 0, height_px_ = 0;
};

} // namespace window
