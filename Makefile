# The two commands of the README: `make render` and `make test`.
# Both install missing Debian packages, configure and build Release.
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all deps configure build render render-mpi test clean test-sanitize fuzz

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

render: build
	@mkdir -p out
	$(BUILD)/bin/raylab render scenes/demo.json -o out/demo.exr --png out/demo.png

# The demo on 2 MPI ranks (needs openmpi-bin: scripts/install-deps.sh --optional). Open MPI
# refuses to run as root unless told so.
MPIRUN ?= mpirun -np 2 $(if $(filter 0,$(shell id -u)),--allow-run-as-root)
render-mpi: build
	@mkdir -p out
	$(MPIRUN) $(BUILD)/bin/raylab render scenes/demo.json -o out/demo_mpi.exr --png out/demo_mpi.png

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-sanitize:
	@$(MAKE) --no-print-directory test BUILD=build-sanitize CMAKE_FLAGS="-DRAYLAB_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo"

# libFuzzer targets for the NFF, JSON and OBJ readers (clang + ASan/UBSan),
# FUZZ_SECONDS each (docs/robustness.md).
FUZZ_SECONDS ?= 60
fuzz:
	@scripts/install-deps.sh --optional
	scripts/fuzz.sh $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD) build-sanitize build-fuzz-targets out
