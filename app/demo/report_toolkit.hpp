// What the report commands (curved-report, lens-report, nonaffine-report)
// share: number formatting, Markdown tables, the timing policy, the error
// of a picture against its reference, the amplified difference picture and
// the PNG writer that records each path.
#pragma once

#include "demo/session.hpp"

#include <image/image.hpp>
#include <reference/curved_reference.hpp>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace demo {

inline constexpr int kDiffGain = 4; // difference pictures: |a - b| x 4 per RGB channel

// `value` with `decimals` digits after the point ("%.*f").
std::string fixed(double value, int decimals);

double milliseconds_since(std::chrono::steady_clock::time_point start);

// A Markdown table: the header row, then one row per call.
class MarkdownTable {
public:
    explicit MarkdownTable(const std::vector<std::string>& header);
    void row(const std::vector<std::string>& cells);
    const std::string& text() const { return text_; }

private:
    std::string text_;
};

// The timing policy: one warm-up run, then `runs` timed ones; `draw` must
// end with the GPU done (a glFinish or a read-back). Reports state which
// statistic they print: the median, or the best when the machine may be shared.
struct Timing {
    double median_ms = 0.0;
    double best_ms = 0.0;
};
frustum::Result<Timing> time_runs(int runs, const std::function<frustum::Status()>& draw);

// |a - b| of every RGB channel (all pixels, or those of `mask`), the share
// of pixels over `threshold_lsb` in some channel.
reference::MirrorError picture_error(const image::Image& a, const image::Image& b, int threshold_lsb);

// |a - b| x kDiffGain per RGB channel; with a mask, the pixels outside it
// show `a` at a quarter of its brightness.
image::Image diff_picture(const image::Image& a, const image::Image& b, const std::vector<bool>* mask = nullptr);

// "mean | max | share%" cells of a picture_error().
std::string error_cells(const reference::MirrorError& e);

// Writes DIR/name as PNG, records the path and reports it as progress.
class PngWriter {
public:
    PngWriter(std::string dir, const Reporter& reporter, std::vector<std::string>& written)
        : dir_(std::move(dir)), reporter_(reporter), written_(written) {}
    frustum::Status operator()(const image::Image& picture, const std::string& name) const;

private:
    std::string dir_;
    const Reporter& reporter_;
    std::vector<std::string>& written_;
};

} // namespace demo
