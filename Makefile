# Front door. `make demo` and `make test` install what is missing (Debian
# packages, via scripts/install-deps.sh), configure, build and run.
BUILD      ?= build
ASAN_BUILD ?= build-asan-clang
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all deps build demo test test-asan test-clang test-arm test-aarch64 test-wasm bench bench-poster fuzz web clean

all: build

deps:
	@bash scripts/install-deps.sh --window

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# Only what scripts/demo.sh runs (frustum-demo, frustum-explain), not the
# test suites: a newcomer sees pictures in minutes. The build directory is
# the same one `make test` completes with everything else.
DEMO_TARGETS := frustum-demo frustum-explain

demo: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target $(DEMO_TARGETS)
	bash scripts/demo.sh $(BUILD)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE web
	@grep -q '^FRUSTUM_TEST_DATA:PATH=.' $(BUILD)/CMakeCache.txt || \
	  echo "make test: the corpus tests were skipped: set FRUSTUM_TEST_DATA to a folder with gltf-samples/ and gltf-validator-corpus/"
	$(MAKE) --no-print-directory test-asan

# The whole suite again under AddressSanitizer + UndefinedBehaviorSanitizer
# (without `package` and `repo`, which build their own trees, not sanitized),
# built with clang++ (the compiler of phones' SDKs): every `make test` runs
# the suite under both compilers.
test-asan:
	@bash scripts/install-deps.sh --window --clang
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DFRUSTUM_SANITIZE=ON -DCMAKE_CXX_COMPILER=clang++ $(CMAKE_FLAGS)
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp \
	  UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -LE 'package|repo|web'

# The whole suite again, built with clang++ (the compiler of phones' SDKs).
test-clang:
	@bash scripts/install-deps.sh --window --clang
	cmake -S . -B build-clang -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ $(CMAKE_FLAGS)
	cmake --build build-clang -j $(JOBS)
	cd build-clang && ctest --output-on-failure -j $(JOBS) -LE web

# The library, the math suite and frustum-vectors with the golden vectors,
# cross-built for ARM and run under qemu: aarch64 with and without FMA
# contraction, armhf baseline (scripts/test-arm.sh).
# test-aarch64 is the first variant alone (FMA contraction, as phones'
# compilers do); .ci/run runs it after make test.
test-arm test-aarch64:
	@bash scripts/install-deps.sh --arm
	JOBS=$(JOBS) CMAKE_FLAGS="$(CMAKE_FLAGS)" bash scripts/test-arm.sh $(if $(filter test-aarch64,$@),aarch64)

# The library and test_math as WebAssembly (emscripten), run under node.
test-wasm:
	@bash scripts/install-deps.sh --web
	JOBS=$(JOBS) bash scripts/test-wasm.sh build-wasm

bench: deps
	@bash scripts/install-deps.sh --bench
	cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DFRUSTUM_BUILD_BENCH=ON $(CMAKE_FLAGS)
	cmake --build build-bench -j $(JOBS)
	bash scripts/bench.sh build-bench

# Posters (issue 36, docs/performance.md "Posters"): the zlib level table on a
# 4096 x 4096 showcase render, then peak RSS and time per megapixel of every
# effect at 4096^2 and 16384^2 and of plain and mirror at 32768^2 (about an
# hour on llvmpipe with 2 cores; POSTER_SIZES / POSTER_EFFECTS to choose).
POSTER_EFFECTS ?= plain mirror tiles frustum curved lens nonaffine portal recursion
bench-poster: deps
	cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DFRUSTUM_BUILD_BENCH=ON $(CMAKE_FLAGS)
	cmake --build build-bench -j $(JOBS) --target frustum-demo poster_zlib
	build-bench/app/demo/frustum-demo render --size 4096x4096 --effect mirror --out build-bench/poster-zlib
	build-bench/tests/bench/poster_zlib build-bench/poster-zlib/mirror.png 1 3 6
	bash scripts/poster-bench.sh build-bench/app/demo/frustum-demo "$${POSTER_SIZES:-4096 16384}" "$(POSTER_EFFECTS)" build-bench/poster-runs
	bash scripts/poster-bench.sh build-bench/app/demo/frustum-demo 32768 "plain mirror" build-bench/poster-runs

# The renderer as one WebGL 2 page (build-web/app/web/frustum-web.html, emscripten)
# and its browser test (CTest label web; slow, so not part of `make test`).
web: deps $(BUILD)/CMakeCache.txt
	@bash scripts/install-deps.sh --web
	JOBS=$(JOBS) bash scripts/build-web.sh build-web
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS) --target frustum-demo web_compare_pngs
	cd $(BUILD) && ctest --output-on-failure -L web

fuzz:
	bash scripts/fuzz.sh $(FUZZ_SECONDS)
clean:
	rm -rf $(BUILD) $(ASAN_BUILD) build-bench build-web build-wasm build-clang build-arm build-count-aarch64 build-count-x86_64
