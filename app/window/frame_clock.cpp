#include "window/frame_clock.hpp"

#include <cstdio>

namespace window {

std::optional<double> FrameClock::tick(TimePoint now) {
    if (!period_start_) {
        period_start_ = now;
        return std::nullopt;
    }
    ++frames_;
    const double elapsed_ms = std::chrono::duration<double, std::milli>(now - *period_start_).count();
    if (elapsed_ms < 500.0) {
        return std::nullopt;
    }
    const double mean_ms = elapsed_ms / frames_;
    period_start_ = now;
    frames_ = 0;
    return mean_ms;
}

std::string window_title(plan::Effect effect, std::optional<double> frame_ms) {
    std::string title = "frustum-demo: " + std::string(plan::to_string(effect));
    if (frame_ms) {
        char text[32];
        std::snprintf(text, sizeof text, " | %.1f ms/frame", *frame_ms);
        title += text;
    }
    return title + " | H: help";
}

} // namespace window
