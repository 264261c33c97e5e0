#include "window/fragment_counter.hpp"

#include "window/pass_rows.hpp"

namespace window {

FragmentCounter::FragmentCounter(const gl::Context& context, const gl::Functions& fn) : fn_(&fn) {
    if (context.api() == gl::Api::Gles) {
        unavailable_ = "n/a: OpenGL ES occlusion queries are boolean (run with --context gl)";
    }
}

void FragmentCounter::start_query(Slot& slot) {
    auto query = slot.queries.next(*fn_);
    if (!query) {
        unavailable_ = "n/a: " + query.error();
        return;
    }
    fn_->BeginQuery(GL_SAMPLES_PASSED, *query);
    slot.counting = true;
}

void FragmentCounter::stop_query(Slot& slot) {
    if (slot.counting) {
        fn_->EndQuery(GL_SAMPLES_PASSED);
        slot.counting = false;
    }
}

bool FragmentCounter::answered(const Slot& slot) const {
    for (std::size_t i = 0; i < slot.names.size(); ++i) {
        GLuint ready = GL_FALSE;
        fn_->GetQueryObjectuiv(slot.queries.id(i), GL_QUERY_RESULT_AVAILABLE, &ready);
        if (ready == GL_FALSE) {
            return false;
        }
    }
    return true;
}

void FragmentCounter::read(Slot& slot) {
    last_passes_.clear();
    for (std::size_t i = 0; i < slot.names.size(); ++i) {
        GLuint samples = 0;
        fn_->GetQueryObjectuiv(slot.queries.id(i), GL_QUERY_RESULT, &samples);
        add_to_pass(last_passes_, slot.names[i], &PassSamples::samples, static_cast<std::uint64_t>(samples));
    }
    slot.pending = false;
}

void FragmentCounter::begin() {
    if (!available()) {
        return;
    }
    // The earlier frames, oldest first: the current slot (three frames
    // back, unread when still unanswered: it is reused now), then the next
    // two; the newest answered one is shown.
    for (int age = 0; age < static_cast<int>(slots_.size()); ++age) {
        Slot& slot = slots_[static_cast<std::size_t>((current_ + age) % static_cast<int>(slots_.size()))];
        if (slot.pending && answered(slot)) {
            read(slot);
        }
    }
    Slot& slot = slots_[static_cast<std::size_t>(current_)];
    slot.pending = false;
    slot.names.clear();
    slot.queries.reset();
    start_query(slot);
}

void FragmentCounter::mark(const char* pass) {
    Slot& slot = slots_[static_cast<std::size_t>(current_)];
    if (!available() || !slot.counting) {
        return;
    }
    stop_query(slot);
    slot.names.emplace_back(pass);
    start_query(slot);
}

void FragmentCounter::end() {
    Slot& slot = slots_[static_cast<std::size_t>(current_)];
    if (!available() || !slot.counting) {
        return;
    }
    stop_query(slot); // the tail after the last mark: not a pass
    slot.pending = true;
    current_ = (current_ + 1) % static_cast<int>(slots_.size());
}

} // namespace window
