// GPU time of the frame's drawing with GL_EXT_disjoint_timer_query
// (OpenGL ES) or ARB_timer_query (desktop GL) when the context has it:
// GL_TIME_ELAPSED queries around each frame, read one frame later (two
// queries in turn, so reading never waits for the GPU). Without the
// extension, or after a disjoint event, the panel shows the CPU wall time
// of the same calls instead, labelled as such.
#pragma once

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

#include <array>
#include <optional>

namespace window {

class GpuTimer {
public:
    // Queries only when the context names one of the extensions.
    GpuTimer(const gl::Context& context, const gl::Functions& fn);

    bool available() const { return get_result_ != nullptr; }
    void begin();
    void end();
    // The last frame's GPU time whose result has arrived, in milliseconds.
    std::optional<double> last_ms() const { return last_ms_; }

private:
    using GetResult = void (*)(GLuint, GLenum, GLuint64*);
    const gl::Functions* fn_;
    GetResult get_result_ = nullptr;
    bool disjoint_query_ = false; // GL_EXT_disjoint_timer_query: check GL_GPU_DISJOINT_EXT
    std::array<gl::Query, 2> queries_;
    std::array<bool, 2> pending_{false, false};
    int current_ = 0;
    std::optional<double> last_ms_;
};

} // namespace window
