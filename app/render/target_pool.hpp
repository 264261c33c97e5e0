// Offscreen targets kept across frames for the recursion pass's views
// (recursion_pass.hpp): a view takes one of exactly its size and format
// (made when none is free) and gives it back once its parent has
// composited it, so later views of the frame and the next frame reuse it.
// end_frame() frees what the frame did not take: a still camera makes no
// target after its first frame, a moving one holds at most one frame's set.
// The pool holds GL objects: destroy it before its context.
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/offscreen_target.hpp>

#include <cstddef>
#include <vector>

namespace render {

class TargetPool {
public:
    // A free target with `options`, else a new one (gl::OffscreenTarget::create's errors).
    frustum::Result<gl::OffscreenTarget> take(const gl::Functions& fn, const gl::OffscreenTargetOptions& options);
    // `target` (made with `options`) free again, kept past the frame's end_frame().
    void give_back(gl::OffscreenTarget target, const gl::OffscreenTargetOptions& options);
    // Frees every target not taken since the last end_frame().
    void end_frame();

    std::size_t made() const { return made_; }       // targets created so far
    std::size_t free_count() const { return free_.size(); }

private:
    struct Entry {
        gl::OffscreenTargetOptions options;
        gl::OffscreenTarget target;
        bool taken = false; // taken since the last end_frame()
    };
    std::vector<Entry> free_;
    std::size_t made_ = 0;
};

} // namespace render
