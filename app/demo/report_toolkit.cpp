#include "demo/report_toolkit.hpp"

#include <image/png.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace demo {

std::string fixed(double value, int decimals) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

MarkdownTable::MarkdownTable(const std::vector<std::string>& header) {
    row(header);
    text_ += "|";
    for (std::size_t i = 0; i < header.size(); ++i) {
        text_ += "---|";
    }
    text_ += "\n";
}

void MarkdownTable::row(const std::vector<std::string>& cells) {
    text_ += "|";
    for (const std::string& cell : cells) {
        text_ += " " + cell + " |";
    }
    text_ += "\n";
}

frustum::Result<Timing> time_runs(int runs, const std::function<frustum::Status()>& draw) {
    std::vector<double> times;
    for (int run = 0; run <= runs; ++run) {
        const auto start = std::chrono::steady_clock::now();
        if (auto status = draw(); !status) {
            return frustum::Error{status.error()};
        }
        if (run > 0) {
            times.push_back(milliseconds_since(start));
        }
    }
    std::sort(times.begin(), times.end());
    return Timing{times[times.size() / 2], times.front()};
}

reference::MirrorError picture_error(const image::Image& a, const image::Image& b, int threshold_lsb) {
    return reference::compare_on_mask(a, b, std::vector<bool>(static_cast<std::size_t>(a.width * a.height), true),
                                      threshold_lsb);
}

image::Image diff_picture(const image::Image& a, const image::Image& b, const std::vector<bool>* mask) {
    image::Image out = image::make_image(a.width, a.height, {0, 0, 0, 255});
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const image::Rgba p = image::pixel_at(a, x, y), q = image::pixel_at(b, x, y);
            const bool inside = !mask || (*mask)[static_cast<std::size_t>(y * a.width + x)];
            image::Rgba o{0, 0, 0, 255};
            for (std::size_t c = 0; c < 3; ++c) {
                const int value = inside ? std::min(255, kDiffGain * std::abs(int{p[c]} - int{q[c]})) : p[c] / 4;
                o[c] = static_cast<std::uint8_t>(value);
            }
            image::set_pixel(out, x, y, o);
        }
    }
    return out;
}

std::string error_cells(const reference::MirrorError& e) {
    return fixed(e.mean_abs, 2) + " | " + std::to_string(e.max_abs) + " | " + fixed(100.0 * e.fraction_over, 2) + "%";
}

frustum::Status PngWriter::operator()(const image::Image& picture, const std::string& name) const {
    const std::string path = dir_ + "/" + name;
    if (auto status = image::write_png(picture, path); !status) {
        return status;
    }
    written_.push_back(path);
    reporter_.progress(path);
    return {};
}

} // namespace demo
