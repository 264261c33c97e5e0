#include "window/gpu_timer.hpp"

namespace window {
namespace {

constexpr GLenum kTimeElapsed = 0x88BF;  // GL_TIME_ELAPSED(_EXT)
constexpr GLenum kGpuDisjoint = 0x8FBB;  // GL_GPU_DISJOINT_EXT

} // namespace

GpuTimer::GpuTimer(const gl::Context& context, const gl::Functions& fn) : fn_(&fn) {
    const bool es = context.has_extension("GL_EXT_disjoint_timer_query");
    if (!es && !context.has_extension("GL_ARB_timer_query")) {
        return;
    }
    const char* name = es ? "glGetQueryObjectui64vEXT" : "glGetQueryObjectui64v";
    auto proc = reinterpret_cast<GetResult>(context.get_proc_address(name));
    for (gl::Query& query : queries_) {
        auto made = gl::Query::create(fn);
        if (!made || !proc) {
            return;
        }
        query = std::move(*made);
    }
    get_result_ = proc;
    disjoint_query_ = es;
}

void GpuTimer::begin() {
    if (!available()) {
        return;
    }
    // The query started two frames ago: its result is read before reusing it.
    if (pending_[current_]) {
        GLuint64 ns = 0;
        get_result_(queries_[current_].id(), GL_QUERY_RESULT, &ns);
        GLint disjoint = 0; // desktop GL has no disjoint events
        if (disjoint_query_) {
            fn_->GetIntegerv(kGpuDisjoint, &disjoint);
        }
        if (disjoint) {
            last_ms_.reset();
        } else {
            last_ms_ = static_cast<double>(ns) * 1e-6;
        }
        pending_[current_] = false;
    }
    fn_->BeginQuery(kTimeElapsed, queries_[current_].id());
}

void GpuTimer::end() {
    if (!available()) {
        return;
    }
    fn_->EndQuery(kTimeElapsed);
    pending_[current_] = true;
    current_ = 1 - current_;
}

} // namespace window
