// GPU time of the frame's drawing with GL_EXT_disjoint_timer_query
// (OpenGL ES) or ARB_timer_query (desktop GL) when the context has it:
// GL_TIME_ELAPSED queries around each frame, read one frame later (two
// queries in turn, so reading never waits for the GPU). Without the
// extension, or after a disjoint event, the panel shows the CPU wall time
// of the same calls instead, labelled as such.
// Per pass: a GL_TIMESTAMP query (glQueryCounter) at begin(), at each
// mark(pass) (render::RenderOptions::pass_end) and at end(); a pass's time
// is the difference of its stamps, read with the frame's (passes of the
// same name summed, window/pass_rows.hpp), and where the stamps answer, the
// frame's time is its last stamp minus its first.
#pragma once

#include "window/query_list.hpp"

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace window {

class GpuTimer {
public:
    // Queries only when the context names one of the extensions.
    GpuTimer(const gl::Context& context, const gl::Functions& fn);

    bool available() const { return get_result_ != nullptr; }
    void begin();
    void mark(const char* pass); // between begin() and end(): `pass` ends here
    void end();
    // The last frame's GPU time whose result has arrived, in milliseconds.
    std::optional<double> last_ms() const { return last_ms_; }

    struct PassTime {
        std::string pass;
        double gpu_ms = 0.0;
    };
    // That frame's passes, in order, one row per name (empty: no marks, or no timestamps).
    const std::vector<PassTime>& last_passes() const { return last_passes_; }

private:
    using GetResult = void (*)(GLuint, GLenum, GLuint64*);
    using QueryCounter = void (*)(GLuint, GLenum);
    // One frame's stamps: [0] at begin(), [i] as names[i - 1] ends, the last at end().
    struct Stamps {
        QueryList queries;
        std::vector<std::string> names;
    };
    void stamp(Stamps& stamps);
    // Fills last_passes_; the frame's milliseconds when its stamps answer.
    std::optional<double> read_stamps(Stamps& stamps);

    const gl::Functions* fn_;
    GetResult get_result_ = nullptr;
    QueryCounter query_counter_ = nullptr;
    std::array<Stamps, 2> stamps_;
    std::vector<PassTime> last_passes_;
    bool disjoint_query_ = false; // GL_EXT_disjoint_timer_query: check GL_GPU_DISJOINT_EXT
    std::array<gl::Query, 2> queries_;
    std::array<bool, 2> pending_{false, false};
    int current_ = 0;
    std::optional<double> last_ms_;
};

} // namespace window
