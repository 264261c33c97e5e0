#!/usr/bin/env bash
# Plots bench_recursion's JSON (recursive mirrors, tight vs full viewport)
# against the depth: OUT_DIR/bench-recursion.png (ms per frame and fragment
# shader invocations per frame, medians).
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
dat=$(mktemp)
trap 'rm -f "$dat"' EXIT
python3 - "$json" > "$dat" <<'PY'
import json, sys
rows = {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    name = b["run_name"].replace("/real_time", "")
    rows[name] = b
print("# depth tight_ms full_ms tight_fs full_fs plan_us")
for d in range(1, 7):
    t, f, p = rows[f"recursion/tight/depth:{d}"], rows[f"recursion/full/depth:{d}"], rows[f"cpu/recursion_plan/depth:{d}"]
    print(d, t["real_time"], f["real_time"], t["fs_invocations"], f["fs_invocations"], p["real_time"])
PY
gnuplot <<GNUPLOT
set terminal pngcairo size 1200,420 font "sans,11"
set output "$out/bench-recursion.png"
set multiplot layout 1,2 title "Two facing mirrors at 1280x720: tight crops + culling vs full viewport + clip plane"
set xlabel "recursion depth"
set grid
set key top left
set ylabel "ms per frame (median)"
set yrange [0:*]
plot "$dat" using 1:3 with linespoints lw 2 pt 7 lc rgb "#9400d3" title "full viewport, clip plane", \
     "" using 1:2 with linespoints lw 2 pt 7 lc rgb "#009e73" title "tight + culling"
set ylabel "fragment shader invocations per frame (millions)"
plot "$dat" using 1:(\$5/1e6) with linespoints lw 2 pt 7 lc rgb "#9400d3" title "full viewport, clip plane", \
     "" using 1:(\$4/1e6) with linespoints lw 2 pt 7 lc rgb "#009e73" title "tight + culling"
unset multiplot
GNUPLOT
echo "$out/bench-recursion.png"
