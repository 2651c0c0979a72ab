# poresph: the two commands of the README. Both install what is missing (Debian 12), build, and run.
# The CUDA backend is compiled whenever nvcc is present (it runs only where a GPU is).
NVCC   := $(firstword $(wildcard /usr/local/cuda/bin/nvcc) $(shell command -v nvcc 2>/dev/null))
PRESET ?= $(if $(NVCC),cuda,cpu-release)
BUILD  := build/$(PRESET)
JOBS   ?= $(shell nproc)

.PHONY: all deps build test demo validate validate-full bench bench-accuracy fuzz images clean

all: build

deps:
	@scripts/install-deps.sh

build: deps
	@cmake --preset $(PRESET) >/dev/null
	@cmake --build --preset $(PRESET) -j $(JOBS)

# Every test (unit, command line, validation at CI size; GPU tests skip without a GPU).
test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# Runs the embedded default case with its figures, served to the browser: prints the URL to open
# (DEMO_PORT, default 8080; the token in the URL allows pause, resume and stop).
DEMO_PORT ?= 8080
demo: build
	@$(BUILD)/solver/poresph demo --serve $(DEMO_PORT) --pipeline phases

validate: build
	@$(BUILD)/solver/poresph validate

validate-full: build
	@$(BUILD)/solver/poresph validate --full

bench: build
	@$(BUILD)/solver/poresph bench

# Run time against error; writes bench/accuracy.json and bench/accuracy.png.
bench-accuracy: build
	@$(BUILD)/solver/poresph bench --accuracy --json > bench/accuracy.json
	@/usr/bin/python3 bench/plot_accuracy.py bench/accuracy.json bench/accuracy.png

# The case-reader and image-reader fuzzers under clang's libFuzzer, FUZZ_SECONDS each (default 600; label fuzz).
FUZZ_SECONDS ?= 600
fuzz:
	@scripts/fuzz.sh $(FUZZ_SECONDS)

# The CPU and GPU container images, built and tested with podman (root; docker/build-and-test.sh).
images:
	@docker/build-and-test.sh all

clean:
	rm -rf build
