// Which clip-space depth range the GPU gets (docs/conventions.md).
// Every camera pair is built with DepthRange::ZeroToOne, the paper's range.
// When the context has clip control it is switched to GL_ZERO_TO_ONE and the
// pairs are used as they are; otherwise GL clips z to [-1, 1] and each pair
// is converted with MatrixPair::with_depth_range(MinusOneToOne) (row 2 only,
// closed-form inverse). Both paths give the same picture.
#pragma once

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>

namespace render {

enum class DepthPath {
    ClipControlWhenAvailable, // [0, 1] with clip control, else the [-1, 1] conversion
    MinusOneToOne,            // always the [-1, 1] conversion (GL's default clip control)
};

class DepthPolicy {
public:
    // Decides the range and sets the context's clip control to match.
    static frustum::Result<DepthPolicy> apply(const gl::Functions& fn, const gl::Context& context,
                                              DepthPath path);

    // What apply() would choose, without touching the context.
    static frustum::DepthRange choose(const gl::Functions& fn, const gl::Context& context, DepthPath path);

    // The range the context clips to: ZeroToOne or MinusOneToOne.
    frustum::DepthRange gpu_range() const { return range_; }

    // The pair as the GPU needs it (a copy when it already is).
    frustum::MatrixPair<float> to_gpu(const frustum::MatrixPair<float>& pair) const;

private:
    explicit DepthPolicy(frustum::DepthRange range) : range_(range) {}
    frustum::DepthRange range_;
};

} // namespace render
