#!/usr/bin/env bash
# Builds the frustum library alone (no app dependencies, -std=c++17,
# -fno-exceptions), installs it into a temporary prefix, then builds and runs
# the consumer project against the installed package.
#   tests/package/run.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
cmake -S "$source_dir" -B "$work/lib" -DFRUSTUM_BUILD_APP=OFF -DFRUSTUM_BUILD_TESTS=OFF \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS="-fno-exceptions -Werror" -DCMAKE_INSTALL_PREFIX="$work/prefix" >/dev/null
cmake --build "$work/lib" -j 2 >/dev/null
cmake --install "$work/lib" >/dev/null
cmake -S "$source_dir/tests/package/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_CXX_FLAGS="-fno-exceptions" >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/consumer"
