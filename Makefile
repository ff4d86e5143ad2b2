# SPDX-License-Identifier: Zlib
# The two commands: `make demo` and `make test`. Everything else is optional.
BUILD     ?= build
OUT       ?= out
JOBS      ?= $(shell nproc)
CMAKE_ARGS ?=
SCENE     ?= demos/scenes/column_bunny.json

FUZZ_BUILD ?= $(BUILD)-fuzz

.PHONY: all deps configure build demo test test-native bench bench-accuracy bench-paper blender-check test-sanitize fuzz-build fuzz-short fuzz-long format format-check clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/demos/btfracture-run $(SCENE) --out $(OUT)/$(basename $(notdir $(SCENE)))

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# The same suite built for this machine's CPU (-march=native) in its own tree; CI runs both.
test-native:
	@$(MAKE) --no-print-directory test BUILD=$(BUILD)-native CMAKE_ARGS="$(CMAKE_ARGS) -DBTFRACTURE_NATIVE=ON"

bench: build
	@scripts/run-bench.sh $(BUILD)

# Python 3 with matplotlib for the charts (Debian's python3-matplotlib is on /usr/bin/python3's
# path, not necessarily on that of the first python3 on PATH); empty when there is none.
CHART_PYTHON ?= $(firstword $(foreach p,/usr/bin/python3 python3,$(shell $(p) -c 'import matplotlib' 2>/dev/null && echo $(p))))

# The accuracy-vs-time study: FULL / EST / HYBRID on every case, about 35 minutes on
# 2 cores (each run capped at 900 s of CPU); runs.csv, steps.csv, table.md and the charts
# (scripts/charts/accuracy_charts.py) into ACCURACY_OUT.
ACCURACY_OUT ?= $(OUT)/accuracy
bench-accuracy: build
	@mkdir -p $(ACCURACY_OUT)
	$(BUILD)/bench/accuracy_vs_time --out $(ACCURACY_OUT)
	@if [ -n "$(CHART_PYTHON)" ]; then $(CHART_PYTHON) scripts/charts/accuracy_charts.py $(ACCURACY_OUT); \
	 else echo "bench-accuracy: no Python 3 with matplotlib (python3-matplotlib): no charts"; fi

# The paper's Table 1 scenes (column, bunny, brick, falling boxes, window) with timings per
# event; about an hour on 2 cores. paper_table.md/.csv and one statistics.csv per scene.
PAPER_OUT ?= bench/results
bench-paper: build
	nice -n 10 $(BUILD)/bench/paper_table --out $(PAPER_OUT)

# The demo's scene.glb imported into Blender headless (Debian's blender, installed by
# `scripts/install-deps.sh blender`): every body an object, every fragment with keyframes.
# Blender is a large install, so this is not part of `make test`.
blender-check: build
	@scripts/install-deps.sh blender
	$(BUILD)/demos/btfracture-run $(SCENE) --out $(OUT)/blender-check --outputs motion,gltf --quiet
	blender -b --factory-startup --python scripts/blender_check.py -- $(OUT)/blender-check/scene.glb \
	  $(OUT)/blender-check/motion.csv

# The unit, scenario and stability suites under ASan + UBSan; the install/consumer tests and
# the second-precision tree (a second whole library build) are left to `make test`. Release
# flags as in `make test`: the fracture outcomes of the stability cases follow the rounding
# (the box's equal edges make remesher ties that rounding breaks), and an -O2 build breaks
# some of them differently. Timeouts are scaled x8 in this tree.
test-sanitize: deps
	@cmake -S . -B $(BUILD)-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Release -DBTFRACTURE_SANITIZE=ON \
	  -DBTFRACTURE_BUILD_BENCH=OFF $(CMAKE_ARGS) > /dev/null
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	ctest --test-dir $(BUILD)-sanitize --output-on-failure -j $(JOBS) -LE package -E '_precision$$'

# Fuzzing needs clang (libFuzzer), so it has its own build tree and is not part of `make test`;
# `make test` replays the seed corpus and every past crash input (CTest fuzz.replay_*).
fuzz-build:
	@scripts/install-deps.sh fuzz
	@cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
	  -DBTFRACTURE_FUZZ=ON -DBTFRACTURE_BUILD_TESTS=OFF -DBTFRACTURE_BUILD_DEMOS=OFF -DBTFRACTURE_BUILD_BENCH=OFF > /dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_targets

fuzz-short: fuzz-build
	@scripts/run-fuzz.sh $(FUZZ_BUILD) short

fuzz-long: fuzz-build
	@scripts/run-fuzz.sh $(FUZZ_BUILD) long

format:
	@scripts/format.sh fix

format-check:
	@scripts/format.sh check

clean:
	rm -rf $(BUILD) $(BUILD)-native $(BUILD)-sanitize $(FUZZ_BUILD) $(OUT)
