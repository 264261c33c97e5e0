#!/usr/bin/env bash
# Installs the Debian packages this project builds and tests with.
# Idempotent: asks apt only for what is missing; uses sudo only when not root.
set -euo pipefail

packages=(
  cmake make g++ pkg-config
  libglm-dev            # vector/matrix math for frustum/
  nlohmann-json3-dev    # JSON for frustum-vectors (tinygltf uses it too)
  libtinygltf-dev       # glTF 2.0 loading
  libdraco-dev          # KHR_draco_mesh_compression: decoding Draco-compressed glTF meshes (app/scene)
  libmeshoptimizer-dev  # EXT_meshopt_compression: decoding meshopt-compressed glTF bufferViews (app/scene)
  draco gltfpack        # draco_transcoder, gltfpack: the scene/gl tests compress the generated torus with them
  libstb-dev            # stb_image_write for PNG output
  libpng-dev            # libpng: posters streamed row by row to PNG (image/png_stream.cpp)
  doctest-dev           # unit tests
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri   # EGL surfaceless + GLES 3
  libosmesa6-dev        # OSMesa offscreen fallback
  libglfw3-dev          # desktop window
  libimgui-dev          # Dear ImGui: the window's control panel (its core; drawn through gl::Functions)
  libbenchmark-dev      # Google Benchmark (bench targets)
  glslang-tools         # glslangValidator: the GLES 3.0 strictness test (tests/gl/glsl_strict_test.cpp)
)
for flag in "$@"; do
  case "$flag" in
    --window) packages+=(xvfb x11-apps imagemagick xdotool) ;; # xdotool: clicks on the window panel (tests/window/panel_clicks.sh)
    --bench) packages+=(gnuplot-nox libeigen3-dev) ;; # scripts/plot-bench.sh; Eigen: a baseline in bench_ops
    --web) packages+=(emscripten chromium) ;; # make web: the WebGL 2 page and its headless-browser test
    --arm) packages+=(g++-aarch64-linux-gnu g++-arm-linux-gnueabihf qemu-user) ;; # make test-arm, test-aarch64
    --clang) packages+=(clang) ;; # make test-clang
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
# Another apt (a second checkout's install, unattended upgrades) may hold
# the dpkg or list locks: wait for them, up to ten minutes, instead of
# failing. DPkg::Lock::Timeout covers dpkg's lock but not the lists' lock
# of `apt-get update` (apt 2.6), hence the loop.
apt_get() {
  local out attempt
  for attempt in $(seq 1 60); do
    if out=$($SUDO apt-get -o DPkg::Lock::Timeout=600 "$@" 2>&1); then
      [ -z "$out" ] || printf '%s\n' "$out"
      return 0
    fi
    if ! grep -q "Could not get lock\|Unable to lock" <<<"$out"; then
      printf '%s\n' "$out" >&2
      return 1
    fi
    echo "install-deps: another apt holds the lock; waiting (attempt $attempt of 60)" >&2
    sleep 10
  done
  printf '%s\n' "$out" >&2
  return 1
}
apt_get update -qq
apt_get install -y -qq --no-install-recommends "${missing[@]}"
