// A framebuffer object to render into: RGBA8 colour (renderbuffer or
// texture) plus a depth renderbuffer, readable as an image::Image. With
// samples > 1 the drawing happens in multisampled colour and depth
// renderbuffers, and resolve() blits the colour into the single-sample
// texture or renderbuffer that color_texture(), read_rgba8() and
// resolved_framebuffer() see (multisampled anti-aliasing).
#pragma once

#include "gl/objects.hpp"

#include <frustum/result.hpp>
#include <image/image.hpp>

namespace gl {

enum class ColorStorage { Renderbuffer, Texture };
// GL_DEPTH_COMPONENT24 / GL_DEPTH_COMPONENT32F; None: colour only (a target
// that is only blitted into or read).
enum class DepthFormat { Depth24, Depth32F, None };

struct OffscreenTargetOptions {
    int width = 0;
    int height = 0;
    ColorStorage color = ColorStorage::Renderbuffer;
    DepthFormat depth = DepthFormat::Depth24;
    int samples = 1; // 1: no multisampling; 2..GL_MAX_SAMPLES: MSAA (choose_samples())
};

// The sample count to draw with: `requested` when 1 <= requested <=
// GL_MAX_SAMPLES, kAutomaticSamples: 4 or the context's maximum when that
// is lower (1 when it has none). Errors name both numbers:
// "gl::choose_samples(): 8 samples requested, but this context offers at most 4 (GL_MAX_SAMPLES)".
inline constexpr int kAutomaticSamples = 0;
inline constexpr int kDefaultSamples = 4;
frustum::Result<int> choose_samples(const Functions& fn, int requested);
// GL_MAX_SAMPLES, at least 1.
int max_samples(const Functions& fn);

class OffscreenTarget {
public:
    // Checks the size against GL_MAX_RENDERBUFFER_SIZE, GL_MAX_TEXTURE_SIZE
    // (texture colour only) and GL_MAX_VIEWPORT_DIMS, e.g.
    // "gl::OffscreenTarget::create(): width and height must be <= GL_MAX_RENDERBUFFER_SIZE=16384, got 20000x64",
    // and names the status of an incomplete framebuffer. Leaves the target bound.
    static frustum::Result<OffscreenTarget> create(const Functions& fn,
                                                   const OffscreenTargetOptions& options);

    // Binds the framebuffer for drawing and reading and sets the viewport to all of it.
    void bind() const;

    // samples > 1: blits the multisampled colour into the single-sample one
    // (the resolve) and binds the drawing framebuffer again. Call it after
    // drawing, before color_texture() or resolved_framebuffer() is read.
    // Leaves the scissor test off. samples == 1: nothing to do.
    void resolve() const;

    // Blits the bottom-left width_px x height_px of what was drawn here
    // (multisampled: resolved on the way) into `to`, a single-sample target,
    // with its corner at (to_x_px, to_y_px) from the bottom-left, and binds
    // this one again: one multisampled target drawn a part at a time can
    // fill several smaller textures, or one larger texture a part at a
    // time. Leaves the scissor test off. Errors: a `to` with samples, a
    // part that does not fit this target or `to` there, e.g.
    // "gl::OffscreenTarget::blit_color_to(): 600x20 pixels at (0, 0) must fit both the 512x256 target and the 600x20 one".
    frustum::Status blit_color_to(const OffscreenTarget& to, int width_px, int height_px, int to_x_px = 0,
                                  int to_y_px = 0) const;

    // After drawing: resolves, then frees what only drawing needs (the
    // multisampled colour, the depth buffer and the drawing framebuffer),
    // keeping the resolved colour: color_texture(), resolved_framebuffer()
    // and read_rgba8() stay valid, bind() and drawing do not. A target that
    // is only sampled from now on (a recursion view waiting for its parent
    // in a poster's tile) then holds 4 bytes a pixel instead of
    // 8 x samples (4x MSAA: 32 bytes) more.
    void keep_resolved_only();

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    // The framebuffer drawn into (multisampled when samples() > 1).
    const Framebuffer& framebuffer() const { return framebuffer_; }
    // The single-sample framebuffer holding the resolved colour: the same as
    // framebuffer() when samples() == 1.
    const Framebuffer& resolved_framebuffer() const { return samples_ > 1 ? resolve_framebuffer_ : framebuffer_; }
    // Empty unless created with ColorStorage::Texture; the resolved colour.
    const Texture& color_texture() const { return color_texture_; }

    // The colour attachment (resolved first), rows top to bottom (GL's start
    // at the bottom). Binds this target and resets the pixel-pack state it relies on.
    frustum::Result<image::Image> read_rgba8() const;
    // The same into columns x_px .. x_px + width() - 1 of `rows`, an image
    // exactly height() high (a poster's row of tiles), without an image of
    // its own: the other columns are left as they are. Errors: a target that
    // does not fit there, e.g.
    // "gl::OffscreenTarget::read_rgba8_into(): a 512x256 target at column 3900 does not fit a 4096x256 image".
    frustum::Status read_rgba8_into(image::Image& rows, int x_px) const;

private:
    OffscreenTarget() = default;
    // The bottom-left width_px x height_px into `to` at the same place.
    void blit_color(const Framebuffer& to, int width_px, int height_px) const;

    const Functions* fn_ = nullptr;
    int width_ = 0;
    int height_ = 0;
    int samples_ = 1;
    Framebuffer framebuffer_;
    Framebuffer resolve_framebuffer_; // samples_ > 1 only
    Renderbuffer multisample_color_;  // samples_ > 1 only
    Texture color_texture_;
    Renderbuffer color_renderbuffer_;
    Renderbuffer depth_renderbuffer_;
};

} // namespace gl
