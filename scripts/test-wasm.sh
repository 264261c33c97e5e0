#!/usr/bin/env bash
# The frustum library and its math suite built with emscripten (Debian's
# 3.1.6: libc++ 13, no floating-point std::to_chars/from_chars, so the
# library's portable number text is what runs) and run by node as
# WebAssembly: the same test_math as on x86-64 and ARM.
#   bash scripts/test-wasm.sh [BUILD_DIR]     (default build-wasm)
# Needs emscripten, node, libglm-dev, doctest-dev (scripts/install-deps.sh --web).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-wasm}
if ! command -v emcmake >/dev/null 2>&1; then
  echo "test-wasm: emscripten not found (emcmake); run scripts/install-deps.sh --web" >&2
  exit 1
fi
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}" # emscripten's acorn with Debian's node
# GLM and doctest are header-only host packages: offered to the cross build
# without putting /usr/include on its path (cmake/toolchains/header-only-deps.cmake).
emcmake cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PROJECT_INCLUDE="$root/cmake/toolchains/header-only-deps.cmake" \
  -DFRUSTUM_BUILD_APP=OFF -DFRUSTUM_BUILD_VECTORS=OFF >/dev/null
# emcmake sets node's --experimental-wasm-threads, which node 20 refuses.
cmake -B "$build" -DCMAKE_CROSSCOMPILING_EMULATOR="$(command -v node)" >/dev/null
cmake --build "$build" -j "${JOBS:-2}" --target test_math
(cd "$build" && ctest --output-on-failure -L math)
