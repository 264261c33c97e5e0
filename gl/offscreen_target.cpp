#include "gl/offscreen_target.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace gl {
namespace {

constexpr const char* kCreate = "gl::OffscreenTarget::create()";

std::string size_text(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

frustum::Status check_size(const Functions& fn, const OffscreenTargetOptions& options) {
    const int w = options.width;
    const int h = options.height;
    if (w < 1 || h < 1) {
        return frustum::Error{std::string(kCreate) + ": width and height must be >= 1, got " +
                              size_text(w, h)};
    }
    struct Limit {
        GLenum name;
        const char* text;
        bool applies;
    };
    const Limit limits[] = {
        {GL_MAX_RENDERBUFFER_SIZE, "GL_MAX_RENDERBUFFER_SIZE", true},
        {GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE", options.color == ColorStorage::Texture},
    };
    for (const Limit& limit : limits) {
        GLint max = 0;
        fn.GetIntegerv(limit.name, &max);
        if (limit.applies && (w > max || h > max)) {
            return frustum::Error{std::string(kCreate) + ": width and height must be <= " +
                                  limit.text + "=" + std::to_string(max) + ", got " + size_text(w, h)};
        }
    }
    GLint viewport[2] = {0, 0};
    fn.GetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    if (w > viewport[0] || h > viewport[1]) {
        return frustum::Error{std::string(kCreate) + ": size must fit GL_MAX_VIEWPORT_DIMS=" +
                              size_text(viewport[0], viewport[1]) + ", got " + size_text(w, h)};
    }
    return {};
}

frustum::Result<Renderbuffer> make_renderbuffer(const Functions& fn, GLenum format, int width,
                                                int height, int samples = 1) {
    auto renderbuffer = Renderbuffer::create(fn);
    if (renderbuffer) {
        fn.BindRenderbuffer(GL_RENDERBUFFER, renderbuffer->id());
        if (samples > 1) {
            fn.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
        } else {
            fn.RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
        }
    }
    return renderbuffer;
}

frustum::Result<Texture> make_color_texture(const Functions& fn, int width, int height) {
    auto texture = Texture::create(fn);
    if (texture) {
        fn.BindTexture(GL_TEXTURE_2D, texture->id());
        fn.TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
        fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    return texture;
}

} // namespace

int max_samples(const Functions& fn) {
    GLint max = 0;
    fn.GetIntegerv(GL_MAX_SAMPLES, &max);
    return std::max(max, 1);
}

frustum::Result<int> choose_samples(const Functions& fn, int requested) {
    const int max = max_samples(fn);
    if (requested == kAutomaticSamples) {
        return std::min(kDefaultSamples, max);
    }
    if (requested < 1 || requested > max) {
        return frustum::Error{"gl::choose_samples(): " + std::to_string(requested) +
                              " samples requested, but this context offers 1 to " + std::to_string(max) +
                              " (GL_MAX_SAMPLES=" + std::to_string(max) + ")"};
    }
    return requested;
}

frustum::Result<OffscreenTarget> OffscreenTarget::create(const Functions& fn,
                                                         const OffscreenTargetOptions& options) {
    if (auto size = check_size(fn, options); !size) {
        return frustum::Error{size.error()};
    }
    if (options.samples < 1 || options.samples > max_samples(fn)) {
        return frustum::Error{std::string(kCreate) + ": samples must be 1.." + std::to_string(max_samples(fn)) +
                              " (GL_MAX_SAMPLES), got " + std::to_string(options.samples)};
    }
    OffscreenTarget target;
    target.fn_ = &fn;
    target.width_ = options.width;
    target.height_ = options.height;
    target.samples_ = options.samples;
    auto framebuffer = Framebuffer::create(fn);
    if (!framebuffer) {
        return frustum::Error{framebuffer.error()};
    }
    target.framebuffer_ = std::move(*framebuffer);
    if (target.samples_ > 1) {
        // The drawing framebuffer: multisampled colour (and depth, below).
        auto resolve = Framebuffer::create(fn);
        auto color = make_renderbuffer(fn, GL_RGBA8, options.width, options.height, target.samples_);
        if (!resolve || !color) {
            return frustum::Error{!resolve ? resolve.error() : color.error()};
        }
        target.resolve_framebuffer_ = std::move(*resolve);
        target.multisample_color_ = std::move(*color);
        fn.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer_.id());
        fn.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                   target.multisample_color_.id());
        // The single-sample colour below goes to the resolve framebuffer.
        fn.BindFramebuffer(GL_FRAMEBUFFER, target.resolve_framebuffer_.id());
    } else {
        fn.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer_.id());
    }

    if (options.color == ColorStorage::Texture) {
        auto texture = make_color_texture(fn, options.width, options.height);
        if (!texture) {
            return frustum::Error{texture.error()};
        }
        target.color_texture_ = std::move(*texture);
        fn.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                target.color_texture_.id(), 0);
    } else {
        auto color = make_renderbuffer(fn, GL_RGBA8, options.width, options.height);
        if (!color) {
            return frustum::Error{color.error()};
        }
        target.color_renderbuffer_ = std::move(*color);
        fn.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                   target.color_renderbuffer_.id());
    }
    if (target.samples_ > 1) {
        if (auto complete = check_framebuffer_complete(fn, GL_FRAMEBUFFER, kCreate); !complete) {
            return frustum::Error{complete.error()};
        }
        fn.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer_.id());
    }
    if (options.depth != DepthFormat::None) {
        const GLenum depth_format =
            options.depth == DepthFormat::Depth24 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT32F;
        auto depth = make_renderbuffer(fn, depth_format, options.width, options.height, target.samples_);
        if (!depth) {
            return frustum::Error{depth.error()};
        }
        target.depth_renderbuffer_ = std::move(*depth);
        fn.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                   target.depth_renderbuffer_.id());
    }

    if (auto error = check_error(fn, kCreate); !error) {
        return frustum::Error{error.error()};
    }
    if (auto complete = check_framebuffer_complete(fn, GL_FRAMEBUFFER, kCreate); !complete) {
        return frustum::Error{complete.error()};
    }
    target.bind();
    return target;
}

void OffscreenTarget::bind() const {
    fn_->BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    fn_->Viewport(0, 0, width_, height_);
}

void OffscreenTarget::keep_resolved_only() {
    resolve();
    if (samples_ > 1) {
        // Deleting the drawing framebuffer first lets the renderbuffers
        // attached to it go (an attached renderbuffer outlives its name).
        fn_->BindFramebuffer(GL_FRAMEBUFFER, resolve_framebuffer_.id());
        framebuffer_ = std::move(resolve_framebuffer_);
        samples_ = 1; // resolved_framebuffer() is framebuffer_ from now on; resolve() has nothing to do
        multisample_color_.reset();
    } else if (depth_renderbuffer_) {
        fn_->BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
        fn_->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    }
    depth_renderbuffer_.reset();
}

void OffscreenTarget::resolve() const {
    if (samples_ <= 1) {
        return;
    }
    blit_color(resolve_framebuffer_, width_, height_);
}

frustum::Status OffscreenTarget::blit_color_to(const OffscreenTarget& to, int width_px, int height_px, int to_x_px,
                                              int to_y_px) const {
    constexpr const char* kBlit = "gl::OffscreenTarget::blit_color_to()";
    if (to.samples_ != 1) {
        return frustum::Error{std::string(kBlit) + ": the target blitted into must have 1 sample, got " +
                              std::to_string(to.samples_)};
    }
    if (width_px < 1 || height_px < 1 || to_x_px < 0 || to_y_px < 0 || width_px > width_ || height_px > height_ ||
        width_px > to.width_ - to_x_px || height_px > to.height_ - to_y_px) {
        return frustum::Error{std::string(kBlit) + ": " + size_text(width_px, height_px) + " pixels at (" +
                              std::to_string(to_x_px) + ", " + std::to_string(to_y_px) + ") must fit both the " +
                              size_text(width_, height_) + " target and the " + size_text(to.width_, to.height_) +
                              " one"};
    }
    if (to_x_px == 0 && to_y_px == 0) {
        blit_color(to.framebuffer_, width_px, height_px);
    } else {
        // A multisampled blit keeps its rectangle (GLES 3.0 §4.3.3): resolve
        // in place first, then move the single-sample pixels.
        if (samples_ > 1) {
            blit_color(resolve_framebuffer_, width_px, height_px);
        }
        fn_->BindFramebuffer(GL_READ_FRAMEBUFFER, resolved_framebuffer().id());
        fn_->ReadBuffer(GL_COLOR_ATTACHMENT0);
        fn_->BindFramebuffer(GL_DRAW_FRAMEBUFFER, to.framebuffer_.id());
        fn_->Disable(GL_SCISSOR_TEST);
        fn_->BlitFramebuffer(0, 0, width_px, height_px, to_x_px, to_y_px, to_x_px + width_px, to_y_px + height_px,
                             GL_COLOR_BUFFER_BIT, GL_NEAREST);
        bind();
    }
    return check_error(*fn_, kBlit);
}

void OffscreenTarget::blit_color(const Framebuffer& to, int width_px, int height_px) const {
    fn_->BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    fn_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    fn_->BindFramebuffer(GL_DRAW_FRAMEBUFFER, to.id());
    fn_->Disable(GL_SCISSOR_TEST); // the blit is scissored too
    fn_->BlitFramebuffer(0, 0, width_px, height_px, 0, 0, width_px, height_px, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    bind();
}

frustum::Result<image::Image> OffscreenTarget::read_rgba8() const {
    image::Image result = image::make_image(width_, height_, {0, 0, 0, 0});
    if (auto read = read_rgba8_into(result, 0); !read) {
        return read.take_error();
    }
    return result;
}

frustum::Status OffscreenTarget::read_rgba8_into(image::Image& rows, int x_px) const {
    if (rows.height != height_ || x_px < 0 || x_px > rows.width - width_ ||
        rows.rgba.size() != static_cast<std::size_t>(rows.width) * static_cast<std::size_t>(rows.height) * 4) {
        return frustum::Error{"gl::OffscreenTarget::read_rgba8_into(): a " + size_text(width_, height_) +
                              " target at column " + std::to_string(x_px) + " does not fit a " +
                              size_text(rows.width, rows.height) + " image"};
    }
    resolve();
    fn_->BindFramebuffer(GL_FRAMEBUFFER, resolved_framebuffer().id());
    fn_->Viewport(0, 0, width_, height_);
    fn_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    fn_->BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    fn_->PixelStorei(GL_PACK_ALIGNMENT, 1);
    fn_->PixelStorei(GL_PACK_ROW_LENGTH, rows.width);
    fn_->PixelStorei(GL_PACK_SKIP_PIXELS, x_px);
    fn_->PixelStorei(GL_PACK_SKIP_ROWS, 0);
    fn_->ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rows.rgba.data());
    fn_->PixelStorei(GL_PACK_ROW_LENGTH, 0);
    fn_->PixelStorei(GL_PACK_SKIP_PIXELS, 0);
    if (auto error = check_error(*fn_, "gl::OffscreenTarget::read_rgba8_into(): glReadPixels"); !error) {
        return frustum::Error{error.error()};
    }
    // GL's rows start at the bottom: flip this target's columns of `rows`.
    const auto row_bytes = static_cast<std::ptrdiff_t>(rows.width) * 4;
    const auto span_bytes = static_cast<std::ptrdiff_t>(width_) * 4;
    auto column = rows.rgba.begin() + static_cast<std::ptrdiff_t>(x_px) * 4;
    for (int top = 0, bottom = height_ - 1; top < bottom; ++top, --bottom) {
        std::swap_ranges(column + top * row_bytes, column + top * row_bytes + span_bytes, column + bottom * row_bytes);
    }
    return {};
}

} // namespace gl
