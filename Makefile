# boreas: thin wrapper over CMake. `make demo` and `make test` work on a fresh Debian machine.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
BUILD_TARGETS ?=
CTEST_FLAGS ?=
# `make test SANITIZE=1` builds into build-sanitize with AddressSanitizer, LeakSanitizer and
# UBSan and runs the whole suite; `make test SANITIZE=thread` builds the tests that use
# threads (label `threads`) into build-tsan with ThreadSanitizer and runs them.
ifeq ($(SANITIZE),1)
BUILD := build-sanitize
CMAKE_FLAGS += -DBOREAS_SANITIZE=ON -DBOREAS_BUILD_BENCH=OFF -DBOREAS_BUILD_PYTHON=OFF
endif
ifeq ($(SANITIZE),thread)
BUILD := build-tsan
CMAKE_FLAGS += -DBOREAS_SANITIZE=thread -DBOREAS_BUILD_BENCH=OFF -DBOREAS_BUILD_RENDER=OFF -DBOREAS_BUILD_PYTHON=OFF
BUILD_TARGETS := --target boreas_thread_tests
CTEST_FLAGS := -L threads
endif

.PHONY: all deps configure build demo test bench soak fuzz install clean

all: build

deps:
	bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j $(JOBS) $(BUILD_TARGETS)

# The main job on the embedded default scene: the 3D view needs OpenGL 4.5, which a machine
# without a display gets from Mesa's llvmpipe under Xvfb.
demo: build
	@if [ -n "$$DISPLAY" ]; then $(BUILD)/render/boreas run --out out/demo; \
	else xvfb-run -a -s "-screen 0 1280x1024x24" $(BUILD)/render/boreas run --out out/demo; fi

test: build
	cd $(BUILD) && ctest --output-on-failure --timeout 900 $(CTEST_FLAGS)

bench: build
	$(BUILD)/bench/boreas_bench --benchmark_counters_tabular=true

# `make soak`: tests/soak/soak.cpp for a simulated hour at 60 Hz and the dt x wind edge
# cases, a table of figures at the end (README, "Soak"). SOAK_ARGS passes options
# (--seed N, --steps N, --dt S, ...; boreas_soak --help).
SOAK_ARGS ?=
soak: configure
	cmake --build $(BUILD) -j $(JOBS) --target boreas_soak
	$(BUILD)/tests/soak/boreas_soak $(SOAK_ARGS)

# `make fuzz`: the libFuzzer harnesses of tests/fuzz (clang, AddressSanitizer, UBSan; the
# library instrumented too) built into build-fuzz, each run for FUZZ_SECONDS (default 60);
# tests/fuzz/README.md says what they cover and holds the last results.
FUZZ_SECONDS ?= 60
FUZZ_TARGETS := fuzz_species_json fuzz_species_growth fuzz_arbaro_xml fuzz_underbrush_species \
  fuzz_obj fuzz_gltf fuzz_scene_json fuzz_tree_cache fuzz_command_line
fuzz:
	bash scripts/install-deps.sh --fuzz
	CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DBOREAS_FUZZ=ON -DBOREAS_BUILD_TESTS=OFF -DBOREAS_BUILD_BENCH=OFF -DBOREAS_BUILD_RENDER=OFF
	cmake --build build-fuzz -j $(JOBS) --target $(FUZZ_TARGETS)
	FUZZ_SECONDS=$(FUZZ_SECONDS) bash tests/fuzz/run.sh build-fuzz

clean:
	rm -rf $(BUILD) build-sanitize build-tsan build-fuzz out
