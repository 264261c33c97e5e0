#include "demo/session.hpp"

#include <string>
#include <utility>

namespace demo {

namespace {

Failure failure_of(const render::OpenFailure& failure) {
    return Failure{failure.usage ? ExitStatus::UsageError : ExitStatus::RuntimeFailure, failure.message};
}

} // namespace

std::variant<LoadedScene, Failure> load_scene(const Settings& settings) {
    auto loaded = render::load_scene(settings);
    if (auto* failure = std::get_if<render::OpenFailure>(&loaded)) {
        return failure_of(*failure);
    }
    return std::move(std::get<LoadedScene>(loaded));
}

gl::ContextOptions context_options(const Settings& settings, const std::function<void(std::string_view)>& note) {
    gl::ContextOptions options;
    if (settings.verbose) {
        options.debug = true;
        options.debug_sink = [note](std::string_view line) { note(line); };
    }
    return options;
}

frustum::Result<std::unique_ptr<gl::Context>> make_context(const Settings& settings, const Reporter& reporter) {
    const gl::ContextOptions options = context_options(settings, reporter.note);
    if (settings.backend) {
        return gl::create_offscreen_context(*settings.backend, options);
    }
    return gl::create_offscreen_context_with_fallback(options, [&reporter](const std::string& egl_error) {
        reporter.note("note: no EGL context (" + egl_error + "); using OSMesa");
    });
}

std::optional<Failure> Session::open(const Settings& settings, const Reporter& reporter, const OpenOptions& how) {
    render::SessionHooks hooks;
    hooks.cameras_at_size = how.cameras_at_size;
    hooks.refuse_explicit = how.refuse_explicit;
    hooks.make_context = how.make_context ? how.make_context
                                          : ContextMaker([&settings, &reporter] { return make_context(settings, reporter); });
    hooks.note = reporter.note;
    if (auto failure = render::Session::open(settings, settings, hooks)) {
        return failure_of(*failure);
    }
    return std::nullopt;
}

} // namespace demo
