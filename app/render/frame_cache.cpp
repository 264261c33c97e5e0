#include "render/frame_cache.hpp"

#include "render/non_affine_pass.hpp"

namespace render {

// Here, where NonAffineUpload is complete.
FrameCache::FrameCache() = default;
FrameCache::~FrameCache() = default;
FrameCache::FrameCache(FrameCache&&) noexcept = default;
FrameCache& FrameCache::operator=(FrameCache&&) noexcept = default;

} // namespace render
