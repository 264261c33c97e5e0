#!/usr/bin/env bash
# Plots docs/images/depth-precision.png (docs/depth-precision.md): metres
# per depth step against the oblique plane's tilt, from
# frustum-depth-precision --data.
#   bash scripts/plot-depth-precision.sh [BUILD_DIR] [OUT_DIR]
# defaults: build and docs/images. Needs gnuplot (scripts/install-deps.sh
# --bench installs gnuplot-nox). Run from the repository's root.
set -euo pipefail
build=${1:-build}
out=${2:-docs/images}
tool="$build/app/precision/frustum-depth-precision"
[ -x "$tool" ] || { echo "plot-depth-precision: no $tool (cmake --build $build --target frustum-depth-precision)" >&2; exit 1; }
if ! command -v gnuplot >/dev/null 2>&1; then
  bash "$(dirname "$0")/install-deps.sh" --bench
fi
mkdir -p "$out"
data=$(mktemp)
trap 'rm -f "$data"' EXIT
"$tool" --data "$data" >/dev/null

gnuplot <<GNUPLOT
set terminal pngcairo size 1560,520 font "sans,11"
set output "$out/depth-precision.png"
set multiplot layout 1,3 title "Depth resolution along the axis of a 60-degree perspective (near 0.1 m, far 100 m) clipped by an oblique plane 0.5-2 m away (median of 64 planes)"
set logscale y
set format y "10^{%T}"
set xlabel "tilt of the oblique plane against the near plane (degrees)"
set ylabel "mm per representable depth step"
set grid
set key top left font ",9"
fixed = "#0072b2"; flt = "#009e73"; rev = "#d55e00"
distances = "2.5 10 50"
do for [i=1:3] {
  set title sprintf("%s m from the eye", word(distances, i))
  plot "$data" index (i-1) using 1:7 with linespoints lw 2 pt 7 lc rgb fixed title "oblique, 24-bit fixed (any range)", \
       "" index (i-1) using 1:9 with linespoints lw 2 pt 7 lc rgb flt title "oblique, float [0,1] / [-1,1]", \
       "" index (i-1) using 1:13 with linespoints lw 2 pt 7 lc rgb rev title "oblique, reversed-Z float", \
       "" index (i-1) using 1:8 with lines lw 1 dt 2 lc rgb fixed title "un-clipped, 24-bit fixed", \
       "" index (i-1) using 1:14 with lines lw 1 dt 2 lc rgb rev title "un-clipped, reversed-Z float"
}
unset multiplot
GNUPLOT
echo "wrote $out/depth-precision.png"
