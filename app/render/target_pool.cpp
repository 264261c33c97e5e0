#include "render/target_pool.hpp"

#include <algorithm>
#include <utility>

namespace render {
namespace {

bool same(const gl::OffscreenTargetOptions& a, const gl::OffscreenTargetOptions& b) {
    return a.width == b.width && a.height == b.height && a.color == b.color && a.depth == b.depth &&
           a.samples == b.samples;
}

} // namespace

frustum::Result<gl::OffscreenTarget> TargetPool::take(const gl::Functions& fn,
                                                      const gl::OffscreenTargetOptions& options) {
    const auto kept = std::find_if(free_.begin(), free_.end(), [&](const Entry& e) { return same(e.options, options); });
    if (kept != free_.end()) {
        gl::OffscreenTarget target = std::move(kept->target);
        free_.erase(kept);
        return target;
    }
    auto made = gl::OffscreenTarget::create(fn, options);
    if (made) {
        ++made_;
    }
    return made;
}

void TargetPool::give_back(gl::OffscreenTarget target, const gl::OffscreenTargetOptions& options) {
    free_.push_back(Entry{options, std::move(target), true});
}

void TargetPool::end_frame() {
    free_.erase(std::remove_if(free_.begin(), free_.end(), [](const Entry& e) { return !e.taken; }), free_.end());
    for (Entry& e : free_) {
        e.taken = false;
    }
}

} // namespace render
