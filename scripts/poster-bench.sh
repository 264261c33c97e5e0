#!/usr/bin/env bash
# Posters (issue 36): peak RSS and time per megapixel of `frustum-demo
# render` posters, per size and effect, as a Markdown table on stdout.
#   scripts/poster-bench.sh DEMO SIZES EFFECTS [OUT_DIR]
#   e.g. scripts/poster-bench.sh build/app/demo/frustum-demo "4096 16384" "plain mirror"
# Each run is one child process under /usr/bin/time -v (its "Maximum
# resident set size" is the peak RSS, as getrusage's ru_maxrss of the child);
# the split into rendering with read-back and PNG compression is the one
# --verbose prints (demo/poster_file.hpp). 4096 fits one target, so it is
# forced through the poster path with --poster-tile 4096x1024, the tile the
# automatic layout picks at that width. The PNGs are deleted after each run.
set -euo pipefail
demo=$1
sizes=$2
effects=$3
out=${4:-$(mktemp -d)}
mkdir -p "$out"
echo "uptime: $(uptime)"
echo
echo "| size | effect | tiles | wall s | Mpx/s | render + read-back s/Mpx | PNG s/Mpx | peak RSS MB | PNG MB |"
echo "|---|---|---|---|---|---|---|---|---|"
for size in $sizes; do
  for effect in $effects; do
    tile=()
    if [ "$size" -le 8192 ]; then tile=(--poster-tile 4096x1024); fi
    log="$out/log-$size-$effect.txt"
    /usr/bin/time -v "$demo" render --size "${size}x${size}" --effect "$effect" "${tile[@]}" --verbose \
      --out "$out/run" >/dev/null 2>"$log"
    layout=$(sed -n 's/.*poster: [0-9x]* in tiles of \([0-9x]*\),.*/\1/p' "$log")
    line=$(grep "poster: $effect.png:" "$log")
    total=$(echo "$line" | sed -n 's/.*png: \([0-9.]*\) s,.*/\1/p')
    rate=$(echo "$line" | sed -n 's/.* \([0-9.]*\) Mpx\/s.*/\1/p')
    render=$(echo "$line" | sed -n 's/.*read-back \([0-9.]*\) s,.*/\1/p')
    png=$(echo "$line" | sed -n 's/.*PNG \([0-9.]*\) s).*/\1/p')
    rss_kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")
    bytes=$(stat -c %s "$out/run/$effect.png")
    awk -v s="$size" -v e="$effect" -v l="$layout" -v t="$total" -v r="$rate" -v rr="$render" -v p="$png" \
        -v kb="$rss_kb" -v b="$bytes" 'BEGIN {
      mpx = s * s / 1e6;
      printf "| %dx%d | %s | %s | %.1f | %.2f | %.4f | %.4f | %.0f | %.1f |\n", s, s, e, l, t, r, rr / mpx, p / mpx,
             kb / 1024, b / 1048576 }'
    rm -f "$out/run/$effect.png"
  done
done
