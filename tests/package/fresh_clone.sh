#!/usr/bin/env bash
# The repository stands on its own: clones SOURCE_DIR's committed HEAD into
# an empty temporary folder (nothing beside the clone, so no path outside the
# repository can resolve), configures it, builds only test_scene and runs
# `ctest -L scene` there, then checks that the corpus tests report a skip
# without FRUSTUM_TEST_DATA. Fails when a file the scene tests need (a
# generated model) is missing from the commit, or a vendored sample folder is in it.
#   tests/package/fresh_clone.sh SOURCE_DIR BUILD_TYPE [COMPILER_LAUNCHER]
# Exit 77 (CTest: skipped) when SOURCE_DIR is not a git repository.
set -euo pipefail
if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: fresh_clone.sh SOURCE_DIR BUILD_TYPE [COMPILER_LAUNCHER]" >&2
  exit 2
fi
source_dir=$1
build_type=$2
launcher=${3:-}

if ! command -v git >/dev/null 2>&1; then
  echo "fresh_clone: SKIPPED: git is not installed, so there is nothing to clone"
  exit 77
fi
top=$(git -C "$source_dir" rev-parse --show-toplevel 2>/dev/null || true)
if [[ -z $top || $(cd "$top" && pwd -P) != $(cd "$source_dir" && pwd -P) ]]; then
  echo "fresh_clone: SKIPPED: $source_dir is not the top of a git repository (an export or a tarball?); this test clones the committed HEAD"
  exit 77
fi
head=$(git -C "$source_dir" rev-parse HEAD)

# Files under tests/data/ that exist here but are not committed would be
# missing from every clone: name them instead of letting the build guess.
untracked=$(git -C "$source_dir" ls-files --others --exclude-standard -- tests/data)
if [[ -n $untracked ]]; then
  echo "fresh_clone: files under tests/data/ are not committed (a clone would not have them):" >&2
  echo "$untracked" | sed 's/^/  /' >&2
  exit 1
fi
if [[ -n $(git -C "$source_dir" status --porcelain --untracked-files=no) ]]; then
  echo "fresh_clone: note: the work tree has uncommitted changes; testing the committed HEAD $head only"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/frustum-fresh-clone.XXXXXX")
trap 'rm -rf "$work"' EXIT
clone=$work/frustum
git clone --quiet --no-checkout --no-hardlinks "$source_dir" "$clone"
git -C "$clone" checkout --quiet --detach "$head"
echo "fresh_clone: $head cloned into $clone (alone in $work)"

# The repository carries only the project's own files: no vendored sample
# folder, and the generated test data is all the scene suite needs.
if [[ -e $clone/tests/data/gltf-samples ]]; then
  echo "fresh_clone: tests/data/gltf-samples is in the commit; third-party corpora are read from FRUSTUM_TEST_DATA" >&2
  exit 1
fi

configure=(-S "$clone" -B "$clone/build" -DCMAKE_BUILD_TYPE="$build_type")
if [[ -n $launcher ]]; then
  configure+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
  # Relative paths in the cache key: every run of this test hits the cache
  # of the previous one although the temporary folder differs.
  export CCACHE_BASEDIR=$clone CCACHE_NOHASHDIR=1
fi
# Alone: no external corpus, whatever the caller's environment names.
unset FRUSTUM_TEST_DATA
cmake "${configure[@]}" >"$work/configure.log" 2>&1 || {
  cat "$work/configure.log" >&2
  echo "fresh_clone: configuring the clone failed (log above)" >&2
  exit 1
}
cmake --build "$clone/build" -j 2 --target test_scene >"$work/build.log" 2>&1 || {
  tail -n 40 "$work/build.log" >&2
  echo "fresh_clone: building test_scene in the clone failed (last lines above)" >&2
  exit 1
}
cd "$clone/build"
ctest -L scene --output-on-failure --no-tests=error
# The loader's corpus tests are there, and report a skip (not a pass) without the corpus.
corpus_log=$work/corpus.log
ctest -R '^corpus-(samples-load|validator)$' --no-tests=error >"$corpus_log" 2>&1 || { cat "$corpus_log" >&2; exit 1; }
skipped=$(grep -c '\*\*\*Skipped' "$corpus_log" || true)
if [[ $skipped -ne 2 ]]; then
  cat "$corpus_log" >&2
  echo "fresh_clone: the two loader corpus tests should report a skip without FRUSTUM_TEST_DATA, $skipped did" >&2
  exit 1
fi
echo "fresh_clone: the corpus tests report a skip without FRUSTUM_TEST_DATA"
