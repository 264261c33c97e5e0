#include "window/gpu_timer.hpp"

#include "window/pass_rows.hpp"

namespace window {
namespace {

constexpr GLenum kTimeElapsed = 0x88BF;  // GL_TIME_ELAPSED(_EXT)
constexpr GLenum kGpuDisjoint = 0x8FBB;  // GL_GPU_DISJOINT_EXT
constexpr GLenum kTimestamp = 0x8E28;    // GL_TIMESTAMP(_EXT)

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
    query_counter_ = reinterpret_cast<QueryCounter>(context.get_proc_address(es ? "glQueryCounterEXT" : "glQueryCounter"));
}

void GpuTimer::stamp(Stamps& stamps) {
    if (!query_counter_) {
        return;
    }
    auto query = stamps.queries.next(*fn_);
    if (!query) {
        return; // no stamp: this frame's passes are left out
    }
    query_counter_(*query, kTimestamp);
}

std::optional<double> GpuTimer::read_stamps(Stamps& stamps) {
    last_passes_.clear();
    std::optional<double> frame_ms;
    // [0] at begin(), one per mark(), the last at end().
    if (stamps.queries.used() == stamps.names.size() + 2) {
        std::vector<GLuint64> ns(stamps.queries.used(), 0);
        for (std::size_t i = 0; i < ns.size(); ++i) {
            get_result_(stamps.queries.id(i), GL_QUERY_RESULT, &ns[i]);
        }
        bool valid = ns[0] != 0; // a context without timestamp bits answers 0
        for (std::size_t i = 1; i < ns.size(); ++i) {
            valid = valid && ns[i] >= ns[i - 1];
        }
        if (valid) {
            for (std::size_t i = 0; i < stamps.names.size(); ++i) {
                add_to_pass(last_passes_, stamps.names[i], &PassTime::gpu_ms,
                            static_cast<double>(ns[i + 1] - ns[i]) * 1e-6);
            }
            frame_ms = static_cast<double>(ns.back() - ns.front()) * 1e-6;
        }
    }
    stamps.names.clear();
    stamps.queries.reset();
    return frame_ms;
}

void GpuTimer::mark(const char* pass) {
    if (!available() || !query_counter_) {
        return;
    }
    Stamps& stamps = stamps_[current_];
    const std::size_t before = stamps.queries.used();
    stamp(stamps);
    if (stamps.queries.used() > before) {
        stamps.names.emplace_back(pass);
    }
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
            last_passes_.clear();
            stamps_[current_].names.clear();
            stamps_[current_].queries.reset();
        } else {
            // The frame from its first and last timestamps where the context
            // has them (llvmpipe's offscreen EGL context answers
            // GL_TIME_ELAPSED with a clock reading, not an interval), else
            // the GL_TIME_ELAPSED query.
            const std::optional<double> stamped_ms = read_stamps(stamps_[current_]);
            last_ms_ = stamped_ms ? *stamped_ms : static_cast<double>(ns) * 1e-6;
        }
        pending_[current_] = false;
    }
    fn_->BeginQuery(kTimeElapsed, queries_[current_].id());
    stamps_[current_].names.clear();
    stamps_[current_].queries.reset();
    stamp(stamps_[current_]);
}

void GpuTimer::end() {
    if (!available()) {
        return;
    }
    stamp(stamps_[current_]);
    fn_->EndQuery(kTimeElapsed);
    pending_[current_] = true;
    current_ = 1 - current_;
}

} // namespace window
