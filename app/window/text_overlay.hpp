// Text over the window's frame (the help panel): window::layout_text()
// triangles on a translucent dark panel, drawn with the renderer's
// flat-colour line program (shaders/line.*), so no shader of its own.
#pragma once

#include <frustum/depth_range.hpp>
#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>
#include <render/programs.hpp>

#include <string>
#include <vector>

namespace window {

class TextOverlay {
public:
    static frustum::Result<TextOverlay> create(const gl::Functions& fn);

    // Draws `lines` (see layout_text) at the top-left of the bound
    // framebuffer, width_px x height_px, blended and without depth test;
    // restores blending off and depth test on. gpu_depth: the clip range
    // the context uses (render::Renderer::gpu_depth_range()). The font is
    // doubled from 720 pixels of height up.
    frustum::Status draw(const render::LineProgram& program, frustum::DepthRange gpu_depth,
                         const std::vector<std::string>& lines, int width_px, int height_px) const;

private:
    TextOverlay(const gl::Functions& fn, gl::Buffer buffer, gl::VertexArray vertex_array);

    const gl::Functions* fn_;
    gl::Buffer buffer_;
    gl::VertexArray vertex_array_;
};

} // namespace window
