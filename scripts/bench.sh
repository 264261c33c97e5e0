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

if [ -x "$build/app/demo/frustum-demo" ] && "$build/app/demo/frustum-demo" bench --help >/dev/null 2>&1; then
  echo "== rendering cost"
  "$build/app/demo/frustum-demo" bench | tee "$out/render_bench.txt"
fi
echo "results in $out/"
