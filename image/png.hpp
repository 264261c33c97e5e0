// PNG files for Image. Writing is atomic: the bytes go to a temporary file
// next to the target, which is renamed over it only once complete, so an
// interrupted run never leaves a partial PNG behind.
#pragma once

#include "image/image.hpp"

#include <frustum/result.hpp>

#include <string>

namespace image {

// Errors name the path and strerror, e.g.
// "image::write_png(): cannot create '/no/dir/a.png.tmp-42-0': No such file or directory".
frustum::Status write_png(const Image& image, const std::string& path);

// Decodes any 8-bit PNG to RGBA8 (grey and RGB gain alpha 255).
frustum::Result<Image> read_png(const std::string& path);

} // namespace image
