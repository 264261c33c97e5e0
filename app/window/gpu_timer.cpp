#include "window/gpu_timer.hpp"

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
    if (stamps.used == stamps.queries.size()) {
        auto made = gl::Query::create(*fn_);
        if (!made) {
            return; // no stamp: this frame's passes are left out
        }
        stamps.queries.push_back(std::move(*made));
    }
    query_counter_(stamps.queries[stamps.used].id(), kTimestamp);
    ++stamps.used;
}

void GpuTimer::read_passes(Stamps& stamps) {
    last_passes_.clear();
    if (stamps.used != stamps.names.size() + 1) {
        stamps.names.clear();
        stamps.used = 0;
        return;
    }
    std::vector<GLuint64> ns(stamps.used, 0);
    for (std::size_t i = 0; i < stamps.used; ++i) {
        get_result_(stamps.queries[i].id(), GL_QUERY_RESULT, &ns[i]);
    }
    for (std::size_t i = 1; i < stamps.used; ++i) {
        if (ns[i] < ns[i - 1] || ns[i] == 0) { // a context without timestamp bits answers 0
            last_passes_.clear();
            break;
        }
        last_passes_.push_back({stamps.names[i - 1], static_cast<double>(ns[i] - ns[i - 1]) * 1e-6});
    }
    stamps.names.clear();
    stamps.used = 0;
}

void GpuTimer::mark(const char* pass) {
    if (!available() || !query_counter_) {
        return;
    }
    Stamps& stamps = stamps_[current_];
    const std::size_t before = stamps.used;
    stamp(stamps);
    if (stamps.used > before) {
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
            stamps_[current_].used = 0;
        } else {
            last_ms_ = static_cast<double>(ns) * 1e-6;
            read_passes(stamps_[current_]);
        }
        pending_[current_] = false;
    }
    fn_->BeginQuery(kTimeElapsed, queries_[current_].id());
    stamps_[current_].names.clear();
    stamps_[current_].used = 0;
    stamp(stamps_[current_]);
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
