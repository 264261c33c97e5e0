// A framebuffer object to render into: RGBA8 colour (renderbuffer or
// texture) plus a depth renderbuffer, readable as an image::Image.
#pragma once

#include "gl/objects.hpp"

#include <frustum/result.hpp>
#include <image/image.hpp>

namespace gl {

enum class ColorStorage { Renderbuffer, Texture };
enum class DepthFormat { Depth24, Depth32F }; // GL_DEPTH_COMPONENT24 / GL_DEPTH_COMPONENT32F

struct OffscreenTargetOptions {
    int width = 0;
    int height = 0;
    ColorStorage color = ColorStorage::Renderbuffer;
    DepthFormat depth = DepthFormat::Depth24;
};

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

    int width() const { return width_; }
    int height() const { return height_; }
    const Framebuffer& framebuffer() const { return framebuffer_; }
    // Empty unless created with ColorStorage::Texture.
    const Texture& color_texture() const { return color_texture_; }

    // The colour attachment, rows top to bottom (GL's start at the bottom).
    // Binds this target and resets the pixel-pack state it relies on.
    frustum::Result<image::Image> read_rgba8() const;

private:
    OffscreenTarget() = default;

    const Functions* fn_ = nullptr;
    int width_ = 0;
    int height_ = 0;
    Framebuffer framebuffer_;
    Texture color_texture_;
    Renderbuffer color_renderbuffer_;
    Renderbuffer depth_renderbuffer_;
};

} // namespace gl
