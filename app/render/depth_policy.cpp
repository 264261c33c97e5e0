#include "render/depth_policy.hpp"

#include <gl/clip_control.hpp>

namespace render {

frustum::DepthRange DepthPolicy::choose(const gl::Functions& fn, const gl::Context& context, DepthPath path) {
    const bool zero_to_one =
        path == DepthPath::ClipControlWhenAvailable && gl::supports_zero_to_one_depth(fn, context);
    return zero_to_one ? frustum::DepthRange::ZeroToOne : frustum::DepthRange::MinusOneToOne;
}

frustum::Result<DepthPolicy> DepthPolicy::apply(const gl::Functions& fn, const gl::Context& context,
                                                DepthPath path) {
    const frustum::DepthRange range = choose(fn, context, path);
    // Disabling also succeeds without clip control ([-1, 1] is then the only mode).
    if (auto status = gl::set_depth_zero_to_one(fn, range == frustum::DepthRange::ZeroToOne); !status) {
        return status.take_error_in("render::DepthPolicy::apply()");
    }
    return DepthPolicy(range);
}

frustum::MatrixPair<float> DepthPolicy::to_gpu(const frustum::MatrixPair<float>& pair) const {
    return pair.depth() == range_ ? pair : pair.with_depth_range(range_);
}

} // namespace render
