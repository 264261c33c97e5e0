#!/usr/bin/env bash
# Builds the frustum library alone (no app dependencies, -std=c++17,
# -fno-exceptions), installs it into a temporary prefix, then builds and runs
# against the installed package: the consumer project, and the README's
# library snippet exactly as printed (the C++ block between the markers
# `<!-- readme-snippet: begin -->` and `<!-- readme-snippet: end -->`).
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

# The README snippet: the lines inside the one ```cpp fence between the markers.
readme=$source_dir/README.md
snippet=$work/readme_snippet.cpp
awk '
  /<!-- readme-snippet: begin -->/ { if (inside) { print "second begin marker" > "/dev/stderr"; exit 3 } inside = 1; found = 1; next }
  /<!-- readme-snippet: end -->/   { inside = 0; next }
  inside && /^```/                 { fence = !fence; next }
  inside && fence                  { print }
  END                              { if (!found || inside) exit 3 }
' "$readme" >"$snippet" || {
  echo "package: README.md has no complete '<!-- readme-snippet: begin -->' ... '<!-- readme-snippet: end -->' block" >&2
  exit 1
}
if ! grep -q "int main" "$snippet"; then
  echo "package: the README snippet ($(wc -l <"$snippet") lines) has no main(); it must be a complete program" >&2
  exit 1
fi
cmake -S "$source_dir/tests/package/readme_snippet" -B "$work/readme" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DSNIPPET_SOURCE="$snippet" -DCMAKE_CXX_FLAGS="-fno-exceptions" >/dev/null
if ! cmake --build "$work/readme" >"$work/readme-build.log" 2>&1; then
  cat "$work/readme-build.log" >&2
  echo "package: the README snippet does not compile against the installed package (errors above; source $snippet)" >&2
  exit 1
fi
echo "package: README snippet ($(wc -l <"$snippet") lines) compiled; running it:"
"$work/readme/readme_snippet"
