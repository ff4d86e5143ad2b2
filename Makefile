# The two commands: `make demo` and `make test`. Everything else is optional.
BUILD     ?= build
OUT       ?= out
JOBS      ?= $(shell nproc)
CMAKE_ARGS ?=
SCENE     ?= demos/scenes/column_bunny.json

.PHONY: all deps configure build demo test bench bench-accuracy test-sanitize format format-check clean

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

bench: build
	@scripts/run-bench.sh $(BUILD)

test-sanitize: deps
	@cmake -S . -B $(BUILD)-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBTFRACTURE_SANITIZE=ON \
	  -DBTFRACTURE_BUILD_BENCH=OFF > /dev/null
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	ctest --test-dir $(BUILD)-sanitize --output-on-failure -j $(JOBS)

format:
	@scripts/format.sh fix

format-check:
	@scripts/format.sh check

clean:
	rm -rf $(BUILD) $(BUILD)-sanitize $(OUT)
