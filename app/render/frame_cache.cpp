#include "render/frame_cache.hpp"

#include "render/curved_pass.hpp"
#include "render/non_affine_pass.hpp"

namespace render {

// Here, where CurvedViews and NonAffineUpload are complete.
FrameCache::FrameCache() = default;
FrameCache::~FrameCache() = default;
FrameCache::FrameCache(FrameCache&&) noexcept = default;
FrameCache& FrameCache::operator=(FrameCache&&) noexcept = default;

} // namespace render
