#!/usr/bin/env bash
# Footprint of BUILD_DIR's frustum-demo, as a Markdown table on stdout:
# file size as built and stripped (a stripped copy; the build is left
# alone), and the peak resident set size (/usr/bin/time -v) of offscreen
# 1280x720 renders of the showcase, next to the same process doing no GL
# (--help) so the driver's share shows.
#   bash scripts/footprint.sh [BUILD_DIR]     (default build-bench)
set -euo pipefail
build=${1:-build-bench}
demo="$build/app/demo/frustum-demo"
[ -x "$demo" ] || { echo "footprint: no $demo (build it first)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

kib() { echo $(( ($(stat -c %s "$1") + 1023) / 1024 )); }
cp "$demo" "$tmp/frustum-demo"
strip "$tmp/frustum-demo"
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null || true)

echo "| what | value |"
echo "|---|---|"
echo "| frustum-demo as built (${build_type:-?}) | $(kib "$demo") KiB |"
echo "| frustum-demo stripped | $(kib "$tmp/frustum-demo") KiB |"
echo "| shared libraries linked (ldd) | $(ldd "$demo" | wc -l) |"

# Peak RSS in KiB of one command (GNU time's "Maximum resident set size").
peak_rss() {
  /usr/bin/time -v "$@" >/dev/null 2>"$tmp/time.txt" || { cat "$tmp/time.txt" >&2; return 1; }
  sed -n 's/^[[:space:]]*Maximum resident set size (kbytes): //p' "$tmp/time.txt"
}
if [ -x /usr/bin/time ]; then
  echo "| peak RSS, \`frustum-demo --help\` (no GL) | $(peak_rss "$demo" --help) KiB |"
  for effect in plain mirror all; do
    rss=$(peak_rss "$demo" render --size 1280x720 --effect "$effect" --out "$tmp/out-$effect")
    echo "| peak RSS, \`render --size 1280x720 --effect $effect\` | $rss KiB |"
  done
else
  echo "| peak RSS | n/a: /usr/bin/time (Debian package time) is missing |"
fi
