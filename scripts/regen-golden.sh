#!/usr/bin/env bash
# Regenerates tests/golden/response-v<N>.json: feeds tests/golden/request-v<N>.json
# to the current frustum-vectors and writes its answer in place (atomically),
# for every version N that has a request file (v1: the original contract;
# v2: portal, jitter, screen_rects and cull).
#
# Run it only after a DELIBERATE change of the library's numbers or of the
# tool's output (the golden test in tests/cli/vectors_golden_test.cpp fails
# on any other change: that is its job), then review `git diff` of the
# responses before committing them: every changed number is a changed answer
# for the ports that check themselves against these files.
#
# A new case goes into the request file of its version (keep its id unique
# and say what it covers); a change of the request format is a new version:
# add request-v<N+1>.json and keep the older files as they are.
#
# Usage: scripts/regen-golden.sh [build-dir]     (default: build)
# The build directory is configured if needed; only frustum-vectors is built.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build"
fi
cmake --build "$build" --target frustum-vectors
tool="$build/app/vectors/frustum-vectors"

for request in "$root"/tests/golden/request-v*.json; do
  response="${request/request-/response-}"
  tmp="$(mktemp "$response.XXXXXX")"
  trap 'rm -f "$tmp"' EXIT
  "$tool" < "$request" > "$tmp"   # exit 2 (a malformed request) stops here
  mv "$tmp" "$response"
  trap - EXIT
  echo "wrote $response ($(grep -c '"ok": true' "$response") ok cases, $(grep -c '"ok": false' "$response") ok: false)"
done
