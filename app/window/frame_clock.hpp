// Frame time for the window title: the mean over about half a second, so
// the number is readable while it changes.
#pragma once

#include <plan/effect.hpp>

#include <chrono>
#include <optional>
#include <string>

namespace window {

class FrameClock {
public:
    using TimePoint = std::chrono::steady_clock::time_point;

    // Call once per frame, at the same point of each frame. Returns the
    // mean time between calls in milliseconds once at least 0.5 s have
    // passed since the last report (or the first call), else nothing.
    std::optional<double> tick(TimePoint now);

private:
    std::optional<TimePoint> period_start_;
    int frames_ = 0;
};

// "frustum-demo: mirror | 4.2 ms/frame | H: help" (the time left out while unknown).
std::string window_title(plan::Effect effect, std::optional<double> frame_ms);

} // namespace window
