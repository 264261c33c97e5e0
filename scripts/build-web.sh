#!/usr/bin/env bash
# Builds the WebGL 2 page with Debian's emscripten into its own build folder:
#   bash scripts/build-web.sh [build-dir]     (default build-web)
# The page: <build-dir>/app/web/frustum-web.html (one self-contained file).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build-web}"
if ! command -v emcmake >/dev/null 2>&1; then
  echo "build-web: emscripten not found (emcmake); run scripts/install-deps.sh --web" >&2
  exit 1
fi
# Debian's emscripten finds its acorn (JS optimizer) through NODE_PATH.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  emcmake cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DFRUSTUM_BUILD_WEB=ON -DFRUSTUM_BUILD_APP=OFF -DFRUSTUM_BUILD_TESTS=OFF
fi
cmake --build "$build" -j "${JOBS:-2}" --target frustum-web
echo "build-web: $build/app/web/frustum-web.html"
