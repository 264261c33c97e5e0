// The CPU benchmarks of bench_render (no GL): per-frame matrix-pair updates
// and the lens tiles.
#pragma once

namespace bench_render {

inline constexpr int kLensTileCounts[] = {4, 8, 16, 32}; // N x N lens tiles
inline constexpr int kCropTileCounts[] = {1, 2, 4, 8, 16, 32}; // N x N crop tiles

// Registers "cpu/frame_updates/{analytic,glm_inverse}" and "cpu/lens_tiles/NxN"
// (frustum::lens_tiles, all the lens effect computes per frame).
void register_cpu_benchmarks();

// Registers "cpu/frame/<effect>/<grid>" (bench_render_frame.cpp): the CPU
// planning of one frame of every effect, showcase at 640x360, no GL.
void register_cpu_frame_benchmarks();
// bench_render --cpu_frame_table: only those, without a GL context; prints
// their medians as a markdown table. Returns the exit status.
int run_cpu_frame_table(int argc, char** argv);

} // namespace bench_render
