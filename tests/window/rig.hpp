// The showcase's renderer on an offscreen context, for the window suite's
// in-process tests; null (after recording a skip with the backend's error) when
// there is no such context.
#pragma once

#include "../plan/showcase.hpp"
#include "../skips.hpp"

#include <doctest/doctest.h>

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <render/renderer.hpp>

#include <memory>
#include <optional>

namespace window_test {

// Members die in reverse: renderer, table, context.
struct Rig {
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<gl::Functions> fn;
    std::optional<render::Renderer> renderer;
};

// `backend` exactly (egl: OpenGL ES, osmesa: desktop core), or unset: EGL, falling back to OSMesa.
inline std::unique_ptr<Rig> make_rig(std::optional<gl::Backend> backend = std::nullopt) {
    auto context = backend ? gl::create_offscreen_context(*backend, {}) : gl::create_offscreen_context_with_fallback({});
    if (!context) {
        test_skips::skip(context.error());
        return nullptr;
    }
    auto rig = std::make_unique<Rig>();
    rig->context = std::move(*context);
    auto fn = gl::Functions::load(*rig->context);
    REQUIRE_MESSAGE(fn.ok(), fn.error());
    rig->fn = std::make_unique<gl::Functions>(*fn);
    auto renderer = render::Renderer::create(*rig->context, *rig->fn, render_test::showcase());
    REQUIRE_MESSAGE(renderer.ok(), renderer.error());
    rig->renderer.emplace(std::move(*renderer));
    return rig;
}

} // namespace window_test
