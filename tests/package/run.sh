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
printed=$("$work/readme/readme_snippet")
echo "$printed"
# Its numbers, derived here without the library: the floor quad's corners
# projected by hand (look-at from (0, 1.7, 6) to (0, 1, 0), fovy 1 rad,
# 1280x720) bound the pixel rectangle; the reflected pass's near plane is the
# floor, its inward normal +y; the eye reflected in y = 0 is at y = -1.70.
expected=$(python3 - <<'PY'
import math
f, aspect, w, h = 1 / math.tan(0.5), 1280 / 720, 1280, 720
eye, target = (0.0, 1.7, 6.0), (0.0, 1.0, 0.0)
sub = lambda p, q: [p[i] - q[i] for i in range(3)]
dot = lambda p, q: sum(p[i] * q[i] for i in range(3))
cross = lambda p, q: [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]
unit = lambda p: [x / math.sqrt(dot(p, p)) for x in p]
forward = unit(sub(target, eye)); side = unit(cross(forward, [0, 1, 0])); up = cross(side, forward)
xs, ys = [], []
for corner in [(-2, 0, -2), (2, 0, -2), (2, 0, 2), (-2, 0, 2)]:
    d = sub(corner, eye); depth = dot(d, forward)
    xs.append((f / aspect * dot(d, side) / depth + 1) / 2 * w)
    ys.append((f * dot(d, up) / depth + 1) / 2 * h)
print("mirror: x %.0f, y %.0f, %.0f x %.0f px; near plane normal y %.2f; reflected eye y %.2f"
      % (min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys), 1.0, -1.7))
PY
)
if [ "$printed" != "$expected" ]; then
  echo "package: the README snippet printed" >&2
  echo "  $printed" >&2
  echo "expected (projected by hand in tests/package/run.sh)" >&2
  echo "  $expected" >&2
  exit 1
fi
echo "package: the README snippet's numbers match the hand projection"
