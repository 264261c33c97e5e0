#!/usr/bin/env bash
# Plots bench_render's results (scripts/bench.sh writes them) as PNGs:
#   OUT_DIR/bench-mirror.png  reflection pass cost vs the mirror's screen size
#   OUT_DIR/bench-tiles.png   N x N crop tiles and lens tiles vs one full frame
#   bash scripts/plot-bench.sh [RESULTS_DIR] [OUT_DIR]
# defaults: build-bench/bench-results and docs/images. Needs gnuplot
# (scripts/install-deps.sh --bench installs gnuplot-nox). Not part of make test.
set -euo pipefail
results=${1:-build-bench/bench-results}
out=${2:-docs/images}
for f in render_mirror.dat render_tiles.dat render_lens.dat; do
  [ -f "$results/$f" ] || { echo "plot-bench: no $results/$f (run bench_render --out_dir=$results)" >&2; exit 1; }
done
if ! command -v gnuplot >/dev/null 2>&1; then
  bash "$(dirname "$0")/install-deps.sh" --bench
fi
mkdir -p "$out"

gnuplot <<GNUPLOT
set terminal pngcairo size 1560,500 font "sans,11"
set output "$out/bench-mirror.png"
clip = "#9400d3"
tight = "#009e73"
set multiplot layout 1,3 title "Mirror reflection pass at 1280x720: tight frustum (mirror + crop) vs full viewport + clip plane"
set logscale x 2
set xrange [0.05:1.25]
set xtics ("1/16" 0.0625, "1/8" 0.125, "1/4" 0.25, "1/2" 0.5, "1/1" 1)
set xlabel "mirror's screen rectangle / frame area"
set key top left
set grid
set ylabel "ms per reflection pass (median of paired frames)"
set yrange [0:*]
plot "$results/render_mirror.dat" using 1:3 with linespoints lw 2 pt 7 lc rgb clip title "clip plane, wall", \
     "" using 1:2 with linespoints lw 2 pt 7 lc rgb tight title "tight, wall", \
     "" using 1:10 with linespoints lw 1 dt 2 pt 6 lc rgb clip title "clip plane, process CPU", \
     "" using 1:9 with linespoints lw 1 dt 2 pt 6 lc rgb tight title "tight, process CPU"
set ylabel "fragments per pass (millions)"
plot "$results/render_mirror.dat" using 1:(\$5/1e6) with linespoints lw 2 pt 7 lc rgb clip title "clip plane, rasterized", \
     "" using 1:(\$4/1e6) with linespoints lw 2 pt 7 lc rgb tight title "tight, rasterized", \
     "" using 1:(\$7/1e6) with linespoints lw 1 dt 2 pt 6 lc rgb clip title "clip plane, FS invocations (llvmpipe)", \
     "" using 1:(\$6/1e6) with linespoints lw 1 dt 2 pt 6 lc rgb tight title "tight, FS invocations (llvmpipe)"
set ylabel "clip plane / tight"
set key top right
plot "$results/render_mirror.dat" using 1:11 with linespoints lw 2 pt 7 lc rgb "#d55e00" title "time, wall (paired)", \
     "" using 1:12 with linespoints lw 1 dt 2 pt 6 lc rgb "#d55e00" title "time, process CPU (paired)", \
     "" using 1:(\$5/\$4) with linespoints lw 2 pt 5 lc rgb "#0072b2" title "rasterized fragments", \
     "" using 1:(\$7/\$6) with linespoints lw 1 dt 2 pt 4 lc rgb "#0072b2" title "FS invocations", \
     3 with lines dt 3 lc rgb "gray40" title "goal at 1/4: 3x"
unset multiplot

set terminal pngcairo size 1000,640 font "sans,11"
set output "$out/bench-tiles.png"
set title "N x N tiles vs one full frame at 1280x720 (median of paired per-frame ratios)"
set logscale x 2
set xrange [0.8:40]
set xtics (1, 2, 4, 8, 16, 32)
set xlabel "tiles per side N (N x N tiles)"
set ylabel "cost / full frame"
set logscale y 2
set yrange [0.8:24]
set ytics (1, 1.2, 1.5, 2, 3, 4, 6, 8, 12, 16)
set key below vertical maxrows 4 width -6
set grid
plot "$results/render_tiles.dat" using 1:6 with linespoints lw 2 pt 7 lc rgb "#9400d3" title "draw\\\\_tiled\\\\_frame (clear per tile), wall", \
     "" using 1:7 with linespoints lw 1 dt 2 pt 6 lc rgb "#9400d3" title "draw\\\\_tiled\\\\_frame, process CPU", \
     "" using 1:8 with linespoints lw 2 pt 5 lc rgb "#0072b2" title "one clear, then tiles, wall", \
     "" using 1:9 with linespoints lw 1 dt 2 pt 4 lc rgb "#0072b2" title "one clear, then tiles, process CPU", \
     "$results/render_lens.dat" using 1:5 with linespoints lw 2 pt 9 lc rgb "#e69f00" title "lens tiles (render::draw\\\\_lens\\\\_frame) vs plain, wall", \
     "" using 1:6 with linespoints lw 1 dt 2 pt 8 lc rgb "#e69f00" title "lens tiles vs plain, process CPU", \
     "" using 1:9 with lines lw 2 dt 4 lc rgb "#cc79a7" title "lens per-pixel reference (1x) vs plain, wall", \
     1.2 with lines dt 3 lc rgb "gray40" title "goal at N = 4: 1.2x"
GNUPLOT
echo "$out/bench-mirror.png"
echo "$out/bench-tiles.png"
