#!/usr/bin/env bash
# Plots bench_recursion's JSON (recursive mirrors, tight vs full viewport,
# layouts "beside" and "room") against the depth: OUT_DIR/bench-recursion.png
# (ms per frame and fragment shader invocations per frame, medians; one row
# of two panels per layout, depth 0 = the camera's own view alone).
#   build/tests/bench/bench_recursion --benchmark_repetitions=5 \
#     --benchmark_report_aggregates_only=true --benchmark_out=recursion.json --benchmark_out_format=json
#   bash scripts/plot-recursion.sh recursion.json [OUT_DIR]
# OUT_DIR defaults to docs/images. Needs gnuplot and python3. Not part of make test.
set -euo pipefail
json=${1:?usage: plot-recursion.sh RESULTS.json [OUT_DIR]}
out=${2:-docs/images}
if ! command -v gnuplot >/dev/null 2>&1; then
  bash "$(dirname "$0")/install-deps.sh" --bench
fi
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$json" "$tmp" <<'PY'
import json, sys
rows = {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    rows[b["run_name"].replace("/real_time", "")] = b
for layout in ("beside", "room"):
    with open(f"{sys.argv[2]}/{layout}.dat", "w") as f:
        print("# depth tight_ms full_ms tight_fs full_fs", file=f)
        for d in range(0, 7):
            t = rows[f"recursion/{layout}/tight/depth:{d}"]
            full = rows[f"recursion/{layout}/full/depth:{d}"]
            print(d, t["real_time"], full["real_time"], t["fs_invocations"], full["fs_invocations"], file=f)
PY
gnuplot <<GNUPLOT
set terminal pngcairo size 1200,800 font "sans,11"
set output "$out/bench-recursion.png"
set multiplot layout 2,2 title "Two facing mirrors at 1280x720: tight crops + culling vs full viewport + clip plane (medians)"
set xlabel "recursion depth"
set grid
set key top left
set offsets 0, 0, graph 0.3, 0
set yrange [0:*]
do for [layout in "beside room"] {
  name = layout eq "beside" ? "beside the showcase's model" : "room, camera looking into one mirror"
  set title name
  set ylabel "ms per frame"
  plot "$tmp/".layout.".dat" using 1:3 with linespoints lw 2 pt 7 lc rgb "#9400d3" title "full viewport, clip plane", \
       "" using 1:2 with linespoints lw 2 pt 7 lc rgb "#009e73" title "tight + culling"
  set ylabel "fragment shader invocations per frame (millions)"
  plot "$tmp/".layout.".dat" using 1:(\$5/1e6) with linespoints lw 2 pt 7 lc rgb "#9400d3" title "full viewport, clip plane", \
       "" using 1:(\$4/1e6) with linespoints lw 2 pt 7 lc rgb "#009e73" title "tight + culling"
}
unset multiplot
GNUPLOT
echo "$out/bench-recursion.png"
