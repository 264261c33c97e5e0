// One frame's GL queries, made the first time a frame needs that many and
// reused by later frames (the GPU timer's timestamps, the fragment
// counter's occlusion queries).
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

#include <cstddef>
#include <vector>

namespace window {

class QueryList {
public:
    // The id of this frame's next query (made when there is none to reuse
    // yet), or the error of making it.
    frustum::Result<GLuint> next(const gl::Functions& fn) {
        if (used_ == queries_.size()) {
            auto made = gl::Query::create(fn);
            if (!made) {
                return made.take_error();
            }
            queries_.push_back(std::move(*made));
        }
        return queries_[used_++].id();
    }
    GLuint id(std::size_t i) const { return queries_[i].id(); }
    std::size_t used() const { return used_; }
    void reset() { used_ = 0; }

private:
    std::vector<gl::Query> queries_;
    std::size_t used_ = 0;
};

} // namespace window
