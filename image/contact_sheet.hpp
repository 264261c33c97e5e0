// Lays several images out on a grid, for looking at test output at a glance.
#pragma once

#include "image/image.hpp"

#include <frustum/result.hpp>

#include <string>
#include <utility>
#include <vector>

namespace image {

// Every cell is as large as the largest image, with a 4-pixel grey border;
// each image sits in the top-left corner of its cell, row-major order.
// Names only serve the error text ("image::contact_sheet(): image 'egl' is null").
frustum::Result<Image> contact_sheet(
    const std::vector<std::pair<std::string, const Image*>>& images, int columns);

} // namespace image
