#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz, a separate clang project) in
# build-fuzz and runs each for the given seconds (default 60), printing the
# executions and whether a crash was found. Not part of `make test`.
#   scripts/fuzz.sh [seconds-per-target]        (make fuzz FUZZ_SECONDS=600)
# Environment: FUZZ_BUILD (build dir), FUZZ_TARGETS ("gltf vectors"), JOBS.
# Inputs found along the way stay in build-fuzz/corpus/<target> (the seeds in
# tests/fuzz/corpus and tests/data/gltf-models are never written); crashes land in
# build-fuzz/artifacts/<target>/ and make the script exit 1.
# Memory: every input runs under a 1536 MiB RSS limit and a 1024 MiB limit
# per allocation (libFuzzer's -rss_limit_mb / -malloc_limit_mb; an address-
# space rlimit cannot be used with ASan's terabytes of shadow mappings). The
# load budget (256 MiB decoded) must refuse first, so an input that gets
# past it to a giant allocation is reported as a crash.
set -euo pipefail

seconds=${1:-60}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${FUZZ_BUILD:-$root/build-fuzz}
targets=${FUZZ_TARGETS:-gltf vectors}
jobs=${JOBS:-2}
[[ $seconds =~ ^[1-9][0-9]*$ ]] || { echo "usage: scripts/fuzz.sh [seconds-per-target]" >&2; exit 2; }
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (apt-get install clang)" >&2; exit 1; }

CC=clang CXX=clang++ cmake -S "$root/tests/fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j "$jobs" --target $(printf 'fuzz_%s ' $targets)
mkdir -p "$build/tmp"
export TMPDIR=$build/tmp # fuzz_gltf's private folders

declare -A max_len=([gltf]=65536 [vectors]=8192)
failed=0
for t in $targets; do
    exe=$build/fuzz_$t
    corpus=$build/corpus/$t
    artifacts=$build/artifacts/$t
    log=$build/fuzz_$t.log
    mkdir -p "$corpus" "$artifacts"
    # Known reproducers first: each must now run clean.
    regressions=("$root/tests/fuzz/regressions/$t"/*)
    if [[ -e ${regressions[0]} ]]; then
        if "$exe" -runs=1 "${regressions[@]}" >"$build/regressions_$t.log" 2>&1; then
            echo "fuzz_$t: ${#regressions[@]} regression inputs run clean"
        else
            echo "fuzz_$t: a regression input still fails, see $build/regressions_$t.log"
            failed=1
        fi
    fi
    # Seeds: the target's corpus folder; for gltf also the generated models
    # and the showcase (scripts/make_feature_gltf.py, make_showcase.py).
    seeds=("$root/tests/fuzz/corpus/$t")
    if [[ $t == gltf ]]; then
        mkdir -p "$build/seeds-gltf"
        cp "$root"/tests/data/gltf-models/*.gl* "$root/assets/showcase.gltf" "$build/seeds-gltf/"
        seeds+=("$build/seeds-gltf")
    fi
    before=$(find "$artifacts" -type f | wc -l)
    status=0
    "$exe" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=1536 -malloc_limit_mb=1024 -max_len="${max_len[$t]:-8192}" \
        -dict="$root/tests/fuzz/$t.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
        "$corpus" "${seeds[@]}" >"$log" 2>&1 || status=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    [[ -n $execs ]] || execs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#')
    after=$(find "$artifacts" -type f | wc -l)
    if [[ $status -eq 0 && $after -eq $before ]]; then
        echo "fuzz_$t: ${execs:-?} executions in ${seconds} s, no crash (log: $log)"
    else
        echo "fuzz_$t: ${execs:-?} executions, FAILED (exit $status), new artifacts in $artifacts:"
        find "$artifacts" -type f -newer "$exe" | sed 's/^/  /'
        grep -m1 -E 'ERROR: (AddressSanitizer|libFuzzer|UndefinedBehaviorSanitizer)|runtime error|contract violation' "$log" | sed 's/^/  /' || true
        failed=1
    fi
done
exit $failed
