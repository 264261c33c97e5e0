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

echo "== speed: analytic update vs build + glm::inverse (one run, side by side)"
"$bench/bench_ops" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/bench_ops.json" --benchmark_out_format=json | tee "$out/bench_ops.txt"

if [ -x "$bench/bench_render" ]; then
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
