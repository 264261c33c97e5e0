#include "image/contact_sheet.hpp"

#include <algorithm>
#include <cstring>

namespace image {
namespace {

constexpr int kBorder = 4;
constexpr Rgba kBackground{64, 64, 64, 255};

void blit(const Image& source, Image& target, int left, int top) {
    const std::size_t row_bytes = static_cast<std::size_t>(source.width) * 4;
    for (int y = 0; y < source.height; ++y) {
        const std::size_t from = static_cast<std::size_t>(y) * row_bytes;
        const std::size_t to =
            (static_cast<std::size_t>(top + y) * static_cast<std::size_t>(target.width) +
             static_cast<std::size_t>(left)) * 4;
        std::memcpy(&target.rgba[to], &source.rgba[from], row_bytes);
    }
}

} // namespace

frustum::Result<Image> contact_sheet(
    const std::vector<std::pair<std::string, const Image*>>& images, int columns) {
    if (images.empty() || columns < 1) {
        return frustum::Error{"image::contact_sheet(): needs at least one image and columns >= 1, got " +
                              std::to_string(images.size()) + " images and columns=" +
                              std::to_string(columns)};
    }
    int cell_width = 0;
    int cell_height = 0;
    for (const auto& [name, picture] : images) {
        if (picture == nullptr) {
            return frustum::Error{"image::contact_sheet(): image '" + name + "' is null"};
        }
        const std::string where = "image::contact_sheet(): image '" + name + "'";
        if (auto valid = validate(*picture, where.c_str()); !valid) {
            return valid.take_error();
        }
        cell_width = std::max(cell_width, picture->width);
        cell_height = std::max(cell_height, picture->height);
    }
    const int count = static_cast<int>(images.size());
    const int used_columns = std::min(columns, count);
    const int rows = (count + columns - 1) / columns;
    Image sheet = make_image(used_columns * (cell_width + kBorder) + kBorder,
                             rows * (cell_height + kBorder) + kBorder, kBackground);
    for (int i = 0; i < count; ++i) {
        blit(*images[static_cast<std::size_t>(i)].second, sheet,
             kBorder + (i % columns) * (cell_width + kBorder),
             kBorder + (i / columns) * (cell_height + kBorder));
    }
    return sheet;
}

} // namespace image
