#!/usr/bin/env bash
# The library (built with -fno-exceptions), the math suite, frustum-vectors
# and its tests with the golden vectors (CTest labels math and cli),
# cross-built for ARM with Debian's cross compilers and run under qemu-user
# (cmake/toolchains/, CMAKE_CROSSCOMPILING_EMULATOR). Variants:
#   aarch64        GCC's default for C++ (-ffp-contract=fast, even with
#                  -std=c++17): a*b+c contracted into fmadd, as phones' code is
#   aarch64-nofma  -ffp-contract=off: x86-64's rounding, operation by operation
#   armhf          ARMv7-A baseline (VFPv3-D16): no fused multiply-add at all
# Each variant builds in build-arm/<variant> only what it runs, then:
#   ctest -L 'math|cli' (every test must pass; the golden cases print their
#   drift from the checked-in x86-64 answers: "golden drift ..."), and the
#   cross-built frustum-vectors executable answers tests/golden/request-v*.json
#   (exit 0; "byte-identical" or not to the checked-in response).
#   bash scripts/test-arm.sh [variant...]     (default: all three)
# Needs g++-aarch64-linux-gnu, g++-arm-linux-gnueabihf, qemu-user, libglm-dev,
# doctest-dev, nlohmann-json3-dev (scripts/install-deps.sh --arm).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
variants=("$@")
[ ${#variants[@]} -gt 0 ] || variants=(aarch64 aarch64-nofma armhf)

for variant in "${variants[@]}"; do
  case $variant in
    aarch64) toolchain=aarch64-linux-gnu flags= sysroot=/usr/aarch64-linux-gnu qemu=qemu-aarch64 ;;
    aarch64-nofma) toolchain=aarch64-linux-gnu flags=-ffp-contract=off sysroot=/usr/aarch64-linux-gnu qemu=qemu-aarch64 ;;
    armhf) toolchain=arm-linux-gnueabihf flags= sysroot=/usr/arm-linux-gnueabihf qemu=qemu-arm ;;
    *) echo "test-arm.sh: unknown variant \"$variant\" (expected aarch64, aarch64-nofma or armhf)" >&2; exit 2 ;;
  esac
  build=$root/build-arm/$variant
  echo "== $variant ($toolchain${flags:+, $flags}) in $build"
  cmake -S "$root" -B "$build" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/$toolchain.cmake" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" \
    -DFRUSTUM_BUILD_APP=OFF -DFRUSTUM_BUILD_VECTORS=ON -DFRUSTUM_NO_EXCEPTIONS=ON ${CMAKE_FLAGS:-} >/dev/null
  cmake --build "$build" -j "$jobs" --target test_math test_cli frustum-vectors
  (cd "$build" && ctest --output-on-failure -j "$jobs" -L 'math|cli')
  grep -o 'golden drift .*' "$build/Testing/Temporary/LastTest.log" | sed "s/^/$variant: /"
  for request in "$root"/tests/golden/request-v*.json; do
    response=${request/request-/response-}
    answer=$build/$(basename "$response")
    "$qemu" -L "$sysroot" "$build/app/vectors/frustum-vectors" <"$request" >"$answer"
    if cmp -s "$answer" "$response"; then same=byte-identical; else same="not byte-identical"; fi
    echo "$variant: frustum-vectors < $(basename "$request"): exit 0, $same to $(basename "$response")"
  done
done
