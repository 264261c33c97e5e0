#!/usr/bin/env bash
# Instructions executed by one call of each hot pair update (success path)
# and of its baseline "new matrix + glm::inverse" (issue 14), on aarch64 (the
# phone-side figure) or x86-64. Builds the library and
# tests/bench/count_driver.cpp with -O3 (as CMake's Release) for the chosen
# target, runs the driver under qemu-user with one instruction per
# translation block and no chaining, and counts the executed blocks
# ("-d exec" prints one line per block):
#   per call = (count(R2 repeats) - count(R1 repeats)) / (R2 - R1) - loop,
# where `loop` is the same for the empty op (the loop's own instructions).
#   bash scripts/count-instructions.sh [aarch64|x86_64] [OUT_DIR] [frame]
#   (default aarch64, OUT_DIR build-count-ARCH; "frame": only the per-frame
#   table of the effects, tests/bench/count_frame_driver.cpp)
# Needs qemu-user, libglm-dev and, for aarch64, g++-aarch64-linux-gnu
# (install-deps.sh --bench --arm).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
arch=${1:-aarch64}
case $arch in
  aarch64)
    cxx=${CXX_AARCH64:-aarch64-linux-gnu-g++}
    qemu=(qemu-aarch64 -L "${AARCH64_SYSROOT:-/usr/aarch64-linux-gnu}")
    ;;
  x86_64)
    cxx=${CXX:-g++}
    qemu=(qemu-x86_64)
    ;;
  *)
    echo "count-instructions.sh: unknown architecture \"$arch\" (expected aarch64 or x86_64)" >&2
    exit 2
    ;;
esac
out=${2:-$root/build-count-$arch}
mkdir -p "$out/include"
# GLM is header-only: expose just it, never the host's /usr/include.
ln -sfn /usr/include/glm "$out/include/glm"
flags=(-std=c++17 -O3 -DNDEBUG -I"$root/frustum/include" -isystem "$out/include" -I"$root/tests/bench")

objects=()
for src in "$root"/frustum/src/*.cpp; do
  obj="$out/$(basename "${src%.cpp}").o"
  if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ -n "$(find "$root/frustum/include" -newer "$obj" -print -quit)" ]; then
    "$cxx" "${flags[@]}" -c "$src" -o "$obj"
  fi
  objects+=("$obj")
done

# The CPU per frame of each effect (tests/bench/count_frame_driver.cpp, the
# rows of bench_render --cpu_frame_table): app/plan built for the target too;
# one frame = count(3 frames) - count(1 frame), halved, the empty frame's
# loop subtracted.
frame_table() {
  local plan_objects=() src obj
  for src in "$root"/app/plan/*.cpp; do
    obj="$out/plan_$(basename "${src%.cpp}").o"
    if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ -n "$(find "$root/app/plan" "$root/app/scene/scene.hpp" "$root/frustum/include" -newer "$obj" -print -quit)" ]; then
      "$cxx" "${flags[@]}" -I"$root" -I"$root/app" -c "$src" -o "$obj"
    fi
    plan_objects+=("$obj")
  done
  "$cxx" "${flags[@]}" -I"$root" -I"$root/app" -static "$root/tests/bench/count_frame_driver.cpp" \
    "${plan_objects[@]}" "${objects[@]}" -o "$out/count_frame_driver"
  count_frame() { # op repeats -> executed instructions of the whole run
    "${qemu[@]}" -singlestep -d exec,nochain -D /dev/stdout "$out/count_frame_driver" "$1" "$2" | grep -c '^Trace'
  }
  per_frame() {
    local a b
    a=$(count_frame "$1" 1)
    b=$(count_frame "$1" 3)
    echo $(((b - a) / 2))
  }
  local empty
  empty=$(per_frame none)
  echo "| effect / grid (showcase, 640x360) | instructions per frame |"
  echo "|---|---:|"
  local op label
  for op in plain:plain/default mirror:mirror/default tiles:tiles/default_3x2 tiles32:tiles/32x32 \
    frustum:frustum/default curved:curved/default_4x4 curved64:curved/max_64x64 lens:lens/default_16x16 \
    lens128:lens/max_128x128 portal:portal/default recursion:recursion/default_depth4 \
    recursion8:recursion/max_depth8 stereo:stereo/default; do
    label=${op#*:}
    echo "| $label | $(($(per_frame "${op%%:*}") - empty)) |"
  done
  echo
  echo "($arch, $("$cxx" --version | head -1); not counted: tiles/max_640x360 (too long under qemu), nonaffine (needs the scene's triangles), curved's curved_tile_size() (GL library))"
}
if [ "${3:-all}" = frame ]; then
  frame_table
  exit 0
fi

"$cxx" "${flags[@]}" -static "$root/tests/bench/count_driver.cpp" "${objects[@]}" -o "$out/count_driver"

count() { # op repeats -> executed instructions of the whole run
  "${qemu[@]}" -singlestep -d exec,nochain -D /dev/stdout "$out/count_driver" "$1" "$2" |
    grep -c '^Trace'
}
r1=10
r2=110
per_call() {
  local a b
  a=$(count "$1" $r1)
  b=$(count "$1" $r2)
  echo $(((b - a) / (r2 - r1)))
}
loop=$(per_call none)
echo "| operation | analytic (library) | new matrix + glm::inverse |"
echo "|---|---|---|"
for op in crop reflect clip mirror; do
  echo "| $op | $(($(per_call "$op") - loop)) | $(($(per_call "${op}_glm") - loop)) |"
done
echo "| glm::inverse alone | - | $(($(per_call glm_inverse) - loop)) |"
echo
echo "($arch, instructions per call on the success path, $("$cxx" --version | head -1), $("${qemu[0]}" --version | head -1); loop overhead $loop subtracted)"

# Batched updates (tests/bench/count_tiles_driver.cpp): one call on a G x G
# grid of a 1280 x 720 image, counted as above with 1 and 3 calls, divided
# by G * G: instructions per tile, the call's fixed part included.
"$cxx" "${flags[@]}" -static "$root/tests/bench/count_tiles_driver.cpp" "${objects[@]}" -o "$out/count_tiles_driver"
count_tiles() { # op G repeats -> executed instructions of the whole run
  "${qemu[@]}" -singlestep -d exec,nochain -D /dev/stdout "$out/count_tiles_driver" "$1" "$2" "$3" |
    grep -c '^Trace'
}
per_tile() { # op G -> instructions per tile of one call
  local a b
  a=$(count_tiles "$1" "$2" 1)
  b=$(count_tiles "$1" "$2" 3)
  echo $(((b - a) / 2 / ($2 * $2)))
}
echo
echo "| batch, per tile | analytic (library) | tiles' matrices + glm::inverse |"
echo "|---|---|---|"
for g in 8 16 32; do
  echo "| crop_tiles ${g} x ${g} | $(per_tile crop_tiles $g) | $(per_tile crop_tiles_glm $g) |"
done
for g in 4 16; do
  echo "| lens_tiles ${g} x ${g} | $(per_tile lens_tiles $g) | $(per_tile lens_tiles_glm $g) |"
done
echo
echo "(instructions per tile, float; the loop around the calls is under 1 per tile)"
echo
echo "| curved-mirror patch fit (fit_volume, double, Newton) | $(per_tile fit_volume 1) instructions per fit |"
echo "|---|---|"
echo
frame_table
