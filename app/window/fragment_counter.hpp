// Fragments per pass: a GL_SAMPLES_PASSED occlusion query (desktop GL
// only: OpenGL ES's occlusion queries answer only whether any sample
// passed) from begin() to the first mark(pass), from there to the next,
// and so on (render::RenderOptions::pass_end marks them, as for the GPU
// timer); what follows the last mark (the inset, the panel) is no pass.
// The count is of samples that passed the depth test: with N-sample MSAA a
// pixel covered once counts N.
//
// Read back without waiting: each frame's queries sit in a ring of three;
// begin() takes every earlier frame whose results have all arrived
// (GL_QUERY_RESULT_AVAILABLE), so last_passes() is a frame or more late,
// and a frame still unanswered when its slot comes round is dropped.
#pragma once

#include "window/query_list.hpp"

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace window {

class FragmentCounter {
public:
    FragmentCounter(const gl::Context& context, const gl::Functions& fn);

    bool available() const { return !unavailable_; }
    // Why there are no counts, for the panel's one line: "n/a: OpenGL ES
    // occlusion queries are boolean (run with --context gl)"; empty when available.
    const std::optional<std::string>& unavailable_reason() const { return unavailable_; }

    void begin();
    void mark(const char* pass); // between begin() and end(): `pass` ends here
    void end();

    struct PassSamples {
        std::string pass;
        std::uint64_t samples = 0; // samples passed (GL_SAMPLES_PASSED), same-named passes summed
    };
    // The newest frame whose counts have arrived, its passes in order
    // (empty before the first one arrives).
    const std::vector<PassSamples>& last_passes() const { return last_passes_; }

private:
    // One frame: queries[i] counts from the (i-1)-th mark (begin() for 0) to the i-th.
    struct Slot {
        QueryList queries;
        std::vector<std::string> names; // names[i] ends queries[i]; one query more (the tail) when ended
        bool pending = false; // ended, not read yet
        bool counting = false;
    };
    void start_query(Slot& slot);
    void stop_query(Slot& slot);
    bool answered(const Slot& slot) const;
    void read(Slot& slot);

    const gl::Functions* fn_;
    std::optional<std::string> unavailable_;
    std::array<Slot, 3> slots_;
    int current_ = 0;
    std::vector<PassSamples> last_passes_;
};

} // namespace window
