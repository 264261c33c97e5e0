#!/usr/bin/env bash
# Posters (issue 36): peak RSS and time per megapixel of `frustum-demo
# render` posters, per size and effect, as a Markdown table on stdout.
#   scripts/poster-bench.sh [--scene city|FILE] DEMO SIZES EFFECTS [OUT_DIR]
#   e.g. nice scripts/poster-bench.sh build/app/demo/frustum-demo "4096 16384" "plain mirror mirror+stereo"
# EFFECTS are --effect names; "E+stereo" is E with --stereo (both eyes side
# by side, each eye a poster of its own camera's crop tiles).
# --scene city: the large scene, a city of 14 x 14 blocks (399 318
# triangles) written by scripts/make_city_gltf.py into the build folder of
# DEMO (the folder above it holding CMakeCache.txt), poster-bench/city.glb,
# at bench time (never committed); --scene FILE: that glTF file (e.g.
# tests/data/gltf-models/box.gltf, a scene with almost no edges); default:
# the showcase.
# Each run is one child process under /usr/bin/time -v: its "Maximum
# resident set size" is the peak RSS (getrusage's ru_maxrss of the child),
# its user + system time the CPU seconds of the whole process (loading the
# scene and the GL context included; llvmpipe's threads count). The split
# into rendering, read-back (each tile after a glFinish) and PNG compression, in wall and in CPU
# seconds, is the one --verbose prints (demo/poster_file.hpp). The machine
# may be loaded: the wall clock then measures the load as much as the
# poster, the CPU seconds much less; "load" is the 1-minute load average
# (/proc/loadavg) as each run starts. 4096 and 8192 fit one target, so they
# are forced through the poster path with --poster-tile auto (the tiles the
# automatic layout picks, render::poster_layout()). The PNGs are deleted
# after each run.
set -euo pipefail
scene=showcase
if [ "${1:-}" = "--scene" ]; then
  scene=$2
  shift 2
fi
if [ $# -lt 3 ]; then
  echo "usage: scripts/poster-bench.sh [--scene city|FILE] DEMO SIZES EFFECTS [OUT_DIR]" >&2
  exit 2
fi
demo=$1
sizes=$2
effects=$3
out=${4:-$(mktemp -d)}
mkdir -p "$out"
scene_args=()
case "$scene" in
  showcase) ;;
  city)
    build=$(cd "$(dirname "$demo")" && pwd)
    while [ "$build" != / ] && [ ! -f "$build/CMakeCache.txt" ]; do build=$(dirname "$build"); done
    if [ ! -f "$build/CMakeCache.txt" ]; then
      echo "poster-bench.sh: no CMakeCache.txt above $demo: --scene city is written into DEMO's build folder" >&2
      exit 2
    fi
    city="$build/poster-bench/city.glb"
    mkdir -p "$(dirname "$city")"
    triangles=$(python3 "$(dirname "$0")/make_city_gltf.py" "$city")
    echo "scene: $city, $triangles triangles"
    scene_args=(--scene "$city")
    ;;
  *)
    if [ ! -f "$scene" ]; then
      echo "poster-bench.sh: --scene must be showcase, city or a glTF file, got $scene" >&2
      exit 2
    fi
    echo "scene: $scene"
    scene_args=(--scene "$scene")
    ;;
esac
echo "uptime: $(uptime)"
echo
echo "| size | effect | tiles | load | wall s | Mpx/s | CPU s/Mpx: render | read-back | PNG | all three | process CPU s/Mpx (user+sys) | peak RSS MB | PNG MB |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for size in $sizes; do
  for token in $effects; do
    effect=${token%+stereo}
    extra=()
    if [ "$effect" != "$token" ]; then extra=(--stereo); fi
    if [ "$size" -le 8192 ]; then extra+=(--poster-tile auto); fi
    log="$out/log-$size-$token.txt"
    load=$(cut -d' ' -f1 /proc/loadavg)
    /usr/bin/time -v "$demo" render --size "${size}x${size}" --effect "$effect" "${extra[@]}" "${scene_args[@]}" \
      --verbose --out "$out/run" >/dev/null 2>"$log"
    layout=$(sed -n 's/.*poster: [0-9x]* in tiles of \([0-9x]*\),.*/\1/p' "$log")
    line=$(grep "poster: $effect.png:" "$log")
    total=$(echo "$line" | sed -n 's/.*png: \([0-9.]*\) s,.*/\1/p')
    rate=$(echo "$line" | sed -n 's/.* \([0-9.]*\) Mpx\/s.*/\1/p')
    render_cpu=$(echo "$line" | sed -n 's/.*CPU: render \([0-9.]*\) s,.*/\1/p')
    read_cpu=$(echo "$line" | sed -n 's/.*CPU: .*read-back \([0-9.]*\) s,.*/\1/p')
    png_cpu=$(echo "$line" | sed -n 's/.*CPU: .*PNG \([0-9.]*\) s).*/\1/p')
    rss_kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")
    user=$(sed -n 's/.*User time (seconds): //p' "$log")
    sys=$(sed -n 's/.*System time (seconds): //p' "$log")
    bytes=$(stat -c %s "$out/run/$effect.png")
    awk -v s="$size" -v e="$token" -v l="$layout" -v ld="$load" -v t="$total" -v r="$rate" \
        -v rc="$render_cpu" -v bc="$read_cpu" -v pc="$png_cpu" -v u="$user" -v sy="$sys" -v kb="$rss_kb" -v b="$bytes" \
        'BEGIN {
      mpx = s * s / 1e6;
      printf "| %dx%d | %s | %s | %s | %.1f | %.2f | %.4f | %.4f | %.4f | %.4f | %.4f | %.0f | %.1f |\n", s, s, e, l,
             ld, t, r, rc / mpx, bc / mpx, pc / mpx, (rc + bc + pc) / mpx, (u + sy) / mpx, kb / 1024, b / 1048576 }'
    rm -f "$out/run/$effect.png"
  done
done
