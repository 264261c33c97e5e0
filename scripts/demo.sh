#!/usr/bin/env bash
# Renders the showcase scene with every effect, nine images (plain, mirror,
# tiles, frustum, curved, lens, nonaffine, portal, recursion), into out/ plus
# a contact sheet, and prints where they are.
# `make demo` runs it as: bash scripts/demo.sh BUILD_DIR
#
#   bash scripts/demo.sh BUILD_DIR [--update-docs]
#
# It first prints a walkthrough of the math on one camera (frustum-explain).
# --update-docs also copies the first four and the sheet into docs/images/
# (the README shows them). Those are tracked files, so only this flag touches them; plain
# `make demo` leaves the work tree as it was. Exits non-zero when anything fails.
set -euo pipefail

usage="usage: bash scripts/demo.sh BUILD_DIR [--update-docs]"
if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "$usage" >&2
  exit 2
fi
build_dir=$1
update_docs=0
if [[ $# -eq 2 ]]; then
  if [[ $2 != --update-docs ]]; then
    echo "demo.sh: unknown option '$2'; $usage" >&2
    exit 2
  fi
  update_docs=1
fi

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
demo=$build_dir/app/demo/frustum-demo
if [[ ! -x $demo ]]; then
  echo "demo.sh: $demo not found; build it first (make demo does)" >&2
  exit 1
fi

explain=$build_dir/app/explain/frustum-explain
if [[ -x $explain ]]; then
  "$explain"
  echo
fi

# 640x360: the main camera's 16:9, a few seconds on llvmpipe.
out=$root/out
written=$("$demo" render --effect all --size 640x360 --out "$out")
echo "demo images (every effect, then the contact sheet):"
while IFS= read -r path; do
  echo "  $path"
done <<< "$written"

if [[ $update_docs -eq 1 ]]; then
  docs=$root/docs/images
  mkdir -p "$docs"
  for name in plain mirror tiles frustum contact_sheet; do
    cp "$out/$name.png" "$docs/$name.png"
  done
  echo "updated $docs/{plain,mirror,tiles,frustum,contact_sheet}.png"
fi
