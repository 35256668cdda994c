# The two commands a new user needs, plus the steps they are made of.
#   make render   install what is missing, build Release, render the reference scene
#   make test     install what is missing, build, run the whole test suite (with the
#                 instruction-count performance gate; not the `long` statistical tests)
BUILD_DIR ?= build
MPI_BUILD_DIR ?= build-mpi
JOBS ?= $(shell nproc)
SCENE ?= scenes/hexroom.json
RENDER_DIR ?= renders

#   make test-asan  the whole suite but the perf gate, built with AddressSanitizer + UBSan
#   make test-tsan  the renderer's multi-threaded tests under ThreadSanitizer
#   make fuzz       every libFuzzer target for FUZZ_SECONDS each (clang-14; tests/fuzz)
SANITIZER_JOBS ?= $(JOBS)
FUZZ_SECONDS ?= 300
FUZZ_BUILD_DIR ?= build-fuzz
ASAN_BUILD_DIR ?= build-asan
TSAN_BUILD_DIR ?= build-tsan
# The tests that run threads: every suite that renders on the thread pool (the render tests'
# helpers render on 2 or 3 threads: both integrators, progressive passes and their stop, resume,
# AOVs, every estimator, light tracing and photons (and the photon grid's threaded build), adaptive sampling, cameras and filters, the
# lights, rough materials, instances, textures and emission textures, alpha-tested materials), the BVH build, the pool itself, and the command
# line's threaded paths through the TSan build of wavetrace (the time limit, resume after a
# signal, a kill during a checkpoint write, adaptive passes), and the MPI render's rank 0 handing
# out chunks beside its own render thread (ChunkDispatch: its threads without MPI, since mpirun
# under TSan is impractical). Not cli.interrupt: TSan holds a signal's handler back until the
# thread reaches one of its own interceptors, so "a second Ctrl-C quits at once" is not at once
# there, and the image may be written before it is seen.
TSAN_RENDERS = Determinism|EdgeSettings|WavefrontVsReference|RayCounts|AccelRender|WhiteFurnace|Progressive|ResumeRender
TSAN_ESTIMATORS = Aov|EstimatorOptions|ClampIndirect|MultipleImportance|LightTracing|Photons|PhotonDeterminism|PhotonGrid|PhotonMaps|AdaptiveDeterminism|AdaptiveSampling
TSAN_SCENES = CameraRender|ConstantEnvironment|DirectionalLight|ListedLights|PointLight|SpotLight|MicrofacetRender|PrincipledRender|InstanceRender|TextureRender|EmissionTexture|AlphaRender
TSAN_SUITES = $(TSAN_RENDERS)|$(TSAN_ESTIMATORS)|$(TSAN_SCENES)|ThreadPool|MemoryEstimate|ChunkDispatch|Bvh\.BuildInvariantsAndDeterminism
TSAN_CLI = time_limit|resume|aov_resume|checkpoint_kill|adaptive
TSAN_TESTS ?= ^($(TSAN_SUITES))\.|/AovIntegrators\.|^cli\.($(TSAN_CLI))$$
TSAN_TARGETS = render_test extremes_test kernels_test hostile_input_test lights_test microfacet_test instance_test \
  texture_test alpha_test chunk_dispatch_test wavetrace

# ccache, where it is installed, for the Release builds: `make test-mpi` then recompiles only
# what MPI changes (the tools), not the core and the kernels `make test` compiled (.ci/run).
CCACHE ?= $(shell command -v ccache 2>/dev/null)
RELEASE_LAUNCHER = $(if $(CCACHE),-DCMAKE_C_COMPILER_LAUNCHER=$(CCACHE) -DCMAKE_CXX_COMPILER_LAUNCHER=$(CCACHE))

.PHONY: render render-mesh reference tradeoff spp-series test test-long test-mpi sanitizer-deps test-asan test-tsan fuzz bench bench-deps perf-gate perf-gate-update build deps configure clean

render: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target wavetrace
	mkdir -p $(RENDER_DIR)
	$(BUILD_DIR)/bin/wavetrace render $(SCENE) -o $(RENDER_DIR)/hexroom.png -o $(RENDER_DIR)/hexroom.exr

# The hexroom with a 1M-triangle displaced sphere loaded from a PLY file through the BVH: the
# mesh files are written first (build/bench-data, about 5 s).
render-mesh: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target wavetrace bench_data
	mkdir -p $(RENDER_DIR)
	$(BUILD_DIR)/bin/wavetrace render $(BUILD_DIR)/bench-data/hexroom_mesh1m.json -o $(RENDER_DIR)/hexroom_mesh1m.png

# The converged reference the error tools compare against (scenes/reference/, committed): the
# hexroom at 200x200, two independent halves of 4096 spp with every accurate option; it prints
# its own noise. About 3 minutes on a quiet 2-core machine. See README, "Error against a reference".
REFERENCE ?= scenes/reference/hexroom_200x200.exr
reference: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target wavetrace
	tools/make_reference.sh $(BUILD_DIR)/bin/wavetrace scenes/hexroom.json $(REFERENCE) 4096 200 200

# The hexroom's speed/accuracy trade table (stdout, build/tradeoff/*.csv) and docs/tradeoff.png:
# about 15 minutes on 2 cores. README, "The speed/accuracy trade".
TRADEOFF_DIR ?= $(BUILD_DIR)/tradeoff
tradeoff: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target wavetrace
	mkdir -p $(TRADEOFF_DIR)
	$(BUILD_DIR)/bin/wavetrace tradeoff $(SCENE) --width 200 --height 200 --reference $(REFERENCE) \
	  --spp 4,16,64,256 --repeats 5 --csv $(TRADEOFF_DIR)/points.csv --fits-csv $(TRADEOFF_DIR)/fits.csv \
	  | tee $(TRADEOFF_DIR)/table.txt
	tools/plot_tradeoff.py $(TRADEOFF_DIR)/points.csv $(TRADEOFF_DIR)/fits.csv docs/tradeoff.png \
	  --title "hexroom 200x200, 2 threads: RMSE against time, one knob changed at a time"

# docs/spp_series.png: the hexroom at 1, 4, 16 and 64 spp, labelled with time and RMSE.
spp-series: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target wavetrace
	tools/spp_series.sh $(BUILD_DIR)/bin/wavetrace $(SCENE) $(REFERENCE) docs/spp_series.png

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -LE long

test-long: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -L long

# The render over MPI ranks (mpirun -np 2 and 3 against one process and a merged split, a
# killed rank): OpenMPI installed, its own build directory with -DWAVETRACE_MPI=ON.
test-mpi: deps
	tools/install-deps.sh libopenmpi-dev openmpi-bin
	cmake -S . -B $(MPI_BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DWAVETRACE_MPI=ON $(RELEASE_LAUNCHER)
	cmake --build $(MPI_BUILD_DIR) -j $(JOBS) --target wavetrace
	cd $(MPI_BUILD_DIR) && ctest --output-on-failure -L mpi

# Sanitizer builds: their own build directories, Debug-free RelWithDebInfo (-O2 -g) so the
# statistical tests stay within their timeouts. The perf gate counts instructions of the
# Release build and is left out. Built with g++: clang-14 compiles the instrumented units
# 2-3x faster (bench/README.md), but its ASan suite still has findings to fix first (issue 19).
SANITIZER_CC ?= CC=clang-14 CXX=clang++-14
sanitizer-deps: deps
	tools/install-deps.sh clang-14 libclang-rt-14-dev

test-asan: deps
	cmake -S . -B $(ASAN_BUILD_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWAVETRACE_SANITIZE=address,undefined -DWAVETRACE_BUILD_BENCHMARKS=OFF -DWAVETRACE_LONG_TESTS=OFF
	cmake --build $(ASAN_BUILD_DIR) -j $(SANITIZER_JOBS)
	cd $(ASAN_BUILD_DIR) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS) -LE 'long|perf'

test-tsan: deps
	cmake -S . -B $(TSAN_BUILD_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWAVETRACE_SANITIZE=thread -DWAVETRACE_BUILD_BENCHMARKS=OFF -DWAVETRACE_LONG_TESTS=OFF
	cmake --build $(TSAN_BUILD_DIR) -j $(SANITIZER_JOBS) --target $(TSAN_TARGETS)
	cd $(TSAN_BUILD_DIR) && TSAN_OPTIONS=halt_on_error=1 ctest --output-on-failure -j $(JOBS) -R '$(TSAN_TESTS)'

# libFuzzer needs clang: clang-14 and its runtime libraries from Debian (sanitizer-deps).
# Only the six targets are built, and they link the core and the command-line parser, none of the
# kernels (tests/fuzz/CMakeLists.txt): the build compiles no unit of src/kernels.
fuzz: sanitizer-deps
	$(SANITIZER_CC) cmake -S . -B $(FUZZ_BUILD_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWAVETRACE_FUZZ=ON -DWAVETRACE_BUILD_TESTS=OFF
	cmake --build $(FUZZ_BUILD_DIR) -j $(SANITIZER_JOBS) --target fuzz_scene fuzz_cli fuzz_obj fuzz_ply fuzz_gltf fuzz_checkpoint
	tests/fuzz/run_fuzzers.sh $(FUZZ_BUILD_DIR) $(FUZZ_SECONDS)

# The benchmarks also install their own optional packages (Embree, the real model) and write
# the benchmark mesh files (build/bench-data) first.
bench: bench-deps
	$(MAKE) build
	cmake --build $(BUILD_DIR) --target bench_data
	$(BUILD_DIR)/bin/bench_intersect
	$(BUILD_DIR)/bin/bench_render

bench-deps: deps
	bench/install-bench-deps.sh

perf-gate: build
	bench/perf_gate.sh $(BUILD_DIR)

perf-gate-update: build
	bench/perf_gate.sh $(BUILD_DIR) --update

deps:
	tools/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(RELEASE_LAUNCHER)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR)
