#!/usr/bin/env bash
# Runs the benchmarks built in BUILD_DIR (default build-bench) and writes the
# raw results under BUILD_DIR/bench-results/. docs/performance.md quotes them.
#   bash scripts/bench.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build-bench}
out="$build/bench-results"
mkdir -p "$out"
bench="$build/tests/bench"

echo "== accuracy of the analytic inverse updates (float vs double reference)"
"$bench/ops_accuracy" 100000 | tee "$out/ops_accuracy.md"

echo "== accuracy of lens_tiles (float vs a double plane construction; issue 34)"
"$bench/lens_accuracy" 200 | tee "$out/lens_accuracy.md"

echo "== speed: analytic update vs build + glm::inverse (one run, side by side)"
# The machine's load before and after: the figures are only comparable
# within one run. Repetitions are interleaved in random order, so a change
# of the machine's speed during the run (a shared host) reaches every
# benchmark alike; medians of 12.
uptime | tee "$out/bench_ops.load"
"$bench/bench_ops" --benchmark_repetitions=12 --benchmark_min_time=0.05 \
  --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/bench_ops.json" --benchmark_out_format=json | tee "$out/bench_ops.txt"
uptime | tee -a "$out/bench_ops.load"

if [ -x "$bench/bench_render" ]; then
  echo "== CPU per frame of every effect, showcase 640x360, no GL (issue 34; medians of 9)"
  uptime | tee "$out/cpu_frame.load"
  "$bench/bench_render" --cpu_frame_table --benchmark_out="$out/cpu_frame.json" \
    --benchmark_out_format=json | tee "$out/cpu_frame.txt"
  uptime | tee -a "$out/cpu_frame.load"
  echo "== rendering cost: tight mirror frustum vs clip plane, tiles, lens tiles, per-frame updates"
  "$bench/bench_render" --out_dir="$out" --benchmark_out="$out/bench_render.json" \
    --benchmark_out_format=json | tee "$out/bench_render.txt"
fi
if [ -x "$build/app/demo/frustum-demo" ]; then
  echo "== footprint"
  bash scripts/footprint.sh "$build" | tee "$out/footprint.md"
fi
if [ -f "$out/render_mirror.dat" ]; then
  echo "plots (docs/images/bench-*.png): bash scripts/plot-bench.sh $out"
fi
echo "results in $out/"
