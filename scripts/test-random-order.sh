#!/usr/bin/env bash
# Runs every doctest suite of a build directory once in a random order
# (doctest --order-by=rand), all with one seed, printed first so that a
# failing order can be rerun: scripts/test-random-order.sh BUILD_DIR SEED.
# Without SEED it is drawn from the clock. Exit 0 when every suite passed,
# 77 when none failed but some skipped (FRUSTUM_REQUIRE_ALL=1 makes a skip
# a failure inside the suite), else 1 with the failing suites named.
# The ES 3.0 reruns of the gl suite are not repeated: the order is what
# this checks, not the context.
set -u
build_dir=$(cd "${1:?usage: scripts/test-random-order.sh BUILD_DIR [SEED]}" && pwd)
seed=${2:-$(( $(date +%s) % 100000 ))}
echo "test-random-order: --order-by=rand --rand-seed=$seed (rerun: $0 $1 $seed)"
failed=() skipped=() ran=0
for suite in math plan scene gl cli robustness window; do
  exe=$(find "$build_dir/tests" -maxdepth 1 -type f -name "test_$suite" -perm -u+x | head -n 1)
  [ -n "$exe" ] || continue
  ran=$((ran + 1))
  echo "== $suite"
  # The external-corpus cases run as tests of their own (tests/CMakeLists.txt).
  (cd "$build_dir/tests" && "$exe" --order-by=rand --rand-seed="$seed" --no-intro=true --test-suite-exclude=corpus-*)
  status=$?
  case $status in
    0) ;;
    77) skipped+=("$suite") ;;
    *) failed+=("$suite (exit $status)") ;;
  esac
done
if [ "$ran" -eq 0 ]; then
  echo "test-random-order: no test_* suite in $build_dir/tests (build them first)" >&2
  exit 1
fi
if [ ${#failed[@]} -gt 0 ]; then
  echo "test-random-order: FAILED with seed $seed: ${failed[*]}" >&2
  exit 1
fi
if [ ${#skipped[@]} -gt 0 ]; then
  echo "test-random-order: passed with seed $seed, but skipped checks in: ${skipped[*]}"
  exit 77
fi
echo "test-random-order: every suite passed with seed $seed"
