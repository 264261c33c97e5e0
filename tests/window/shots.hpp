// Window screenshots against offscreen renders, for the window suite's
// tests that run `frustum-demo window` under xvfb-run.
//
// Tolerance: RGB within 2 per channel on all but 0.5% of the pixels (alpha
// is not compared: the window is opaque). With Mesa's llvmpipe behind both
// the surfaceless and the X11 EGL display the images are bit-identical; the
// slack is for drivers whose window and surfaceless paths differ.
#pragma once

#include "process.hpp"

#include "support/temp_dir.hpp"

#include <image/image.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace window_test {

inline constexpr int kTolerance = 2;
inline constexpr double kMaxFractionOver = 0.005;

inline const std::string kDemo = FRUSTUM_DEMO_EXE;

// `frustum-demo window options...` under xvfb-run; empty (after recording a skip) when xvfb-run is missing.
std::optional<Child> run_window_under_xvfb(const std::vector<std::string>& options);

image::Image read(const std::filesystem::path& path);

// The offscreen renderer's image of `effect` at `size` ("WxH"), in dir/render.
image::Image render_offscreen(const support::TempDir& dir, const std::string& effect, const std::string& size,
                              const std::vector<std::string>& more = {});

// The pixels of `picture` inside [x0, x1) x [y0, y1) (rows from the top).
image::Image crop(const image::Image& picture, int x0, int y0, int x1, int y1);

// CHECKs that RGB differs by more than kTolerance on at most kMaxFractionOver of the pixels.
void check_similar(const image::Image& window, const image::Image& offscreen, const std::string& what);

// Pixels whose RGB differs by more than kTolerance (the images' sizes must match).
int pixels_differing(const image::Image& a, const image::Image& b);

} // namespace window_test
