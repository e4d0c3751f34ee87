# hertzdash top-level targets. `make figures` and `make test` are the two
# commands the README promises; both install missing Debian packages first.
BUILD   ?= build
JOBS    ?= $(shell nproc)
FIGURES ?= paper/figures
# Instrumented builds, each in a folder of its own (docs/reliability.md).
SANITIZE_BUILD ?= build-sanitize
FUZZ_BUILD     ?= build-fuzz
# The scratch build of `make build-times`.
BUILD_TIMES_BUILD ?= build-times
FUZZ_SECONDS   ?= 60
# Extra CMake arguments for every configuration, e.g. CMAKE_ARGS=-DCMAKE_CXX_COMPILER_LAUNCHER=ccache
CMAKE_ARGS     ?=

.PHONY: all deps deps-paper deps-peers deps-engines configure build test figures convergence uncertainty gas paper bench build-times sanitize fuzz clean

all: build

# What building, the studies and the figures need; TeX (debian-packages-paper.txt) is installed
# only for what builds the article: `make paper` and `make test` (the suite builds the paper).
deps:
	@tools/install-deps.sh debian-packages.txt

deps-paper:
	@tools/install-deps.sh debian-packages.txt debian-packages-paper.txt

# The discrete-element engines the suite runs hertzdash's decks in (debian-packages-engines.txt).
deps-engines:
	@tools/install-deps.sh debian-packages.txt debian-packages-engines.txt

# The peer engines `make bench` runs (debian-packages-peers.txt).
deps-peers:
	@tools/install-deps.sh debian-packages.txt debian-packages-peers.txt

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build deps-paper deps-engines
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The studies of bench/ are among the figures: a build without the benchmark peers
# (HERTZDASH_WITH_BENCH, docs/layout.md "Optional parts") cannot make them.
need_bench = @[ -x $(BUILD)/bench/work_precision_peers ] || { echo "make $@: $(BUILD) was built without the benchmark\
peers (bench/: Boost.Odeint, HERTZDASH_WITH_BENCH; Debian: libboost-dev), which the figures and the article include" >&2; exit 2; }

figures: build deps-engines
	$(need_bench)
	validation/run_studies.sh $(BUILD) $(FIGURES)

# Convergence: the order tests (verbose, so their tables print), then the study's
# full order tables (its CSV and LaTeX go to a scratch directory; `make figures`
# writes the real ones).
convergence: build
	cd $(BUILD) && ctest -L convergence --output-on-failure -V
	$(BUILD)/validation/convergence --out $(BUILD)/convergence/figures

# The joint uncertainty study at its full sample size (N = 65536 Sobol rows per rod, 2.6
# million impacts, over a minute on 2 cores; `make figures` runs it with N = 4096): its CSV,
# figures and the article's \uq macros, overwriting those of `make figures`.
uncertainty: build
	$(BUILD)/validation/uncertainty --full --out $(FIGURES) --generated paper/generated
	for gp in validation/uncertainty/*.gp; do validation/draw_figure.sh $$gp $(FIGURES) || exit 1; done

# The granular gas at its full size (13824 spheres, each law for 40 Haff times on LAMMPS under
# mpirun -n 2, a few minutes; `make figures` runs 1000 for 12): its CSV, figure and the article's \gas macros.
gas: build deps-engines
	$(BUILD)/validation/gas_cooling --full --out $(FIGURES) --generated paper/generated
	validation/draw_figure.sh validation/gas_cooling/gas_cooling.gp $(FIGURES)

# The article: every study and figure, then latexmk in paper/. The date in the PDF
# is the last commit's (SOURCE_DATE_EPOCH), so the same commit gives the same PDF.
paper: figures deps-paper
	@epoch=$$(git log -1 --format=%ct 2>/dev/null); \
	if [ -n "$$epoch" ]; then export SOURCE_DATE_EPOCH=$$epoch FORCE_SOURCE_DATE=1; fi; \
	paper/build.sh paper

# Work precision against Boost.Odeint, GSL and CVODE at full repeats (a few minutes):
# prints the table and ratios, writes the CSVs the figure is drawn from, the paper's
# \perf macros, and the measured block of docs/performance.md.
# It first times `make figures` from the built tree (into a scratch directory). Then the peer
# engines beside hertzdash on the same impacts (bench/siconos_peer/siconos_peer.py: Siconos's
# event-driven bouncing ball, the same orbits, the time per impact of each).
bench: build deps-peers deps-engines
	$(need_bench)
	@start=$$(date +%s%N); \
	validation/run_studies.sh $(BUILD) $(BUILD)/figures-timing > /dev/null; \
	ms=$$(( ($$(date +%s%N) - start) / 1000000 )); \
	$(BUILD)/bench/work_precision_peers --full --out $(FIGURES) --generated paper/generated --performance-page docs/performance.md \
	  --figures-ms $$ms
	validation/draw_figure.sh bench/work_precision_peers/work_precision_peers.gp $(FIGURES)
	/usr/bin/python3 bench/siconos_peer/siconos_peer.py $(BUILD)

# The cold build and the rebuild after editing one damping law's header, ccache off, in a scratch
# directory of their own (tools/measure-build-times.sh): the generated blocks of docs/build-times.md
# and of the README. Half an hour and more on 2 cores.
build-times: deps-paper
	tools/measure-build-times.sh $(BUILD_TIMES_BUILD) $(JOBS)

# The whole ctest suite under AddressSanitizer + UndefinedBehaviorSanitizer, every report fatal
# (cmake/sanitizers.cmake). Leaks are checked (LSan) but for the Python interpreter's and Open MPI's
# (tests/CMakeLists.txt, tests/lsan-suppressions.txt). -O1 with assertions on: -O3 took several
# minutes and 2.5 GB for one template-heavy file under ASan. paper_builds is left out: it runs every
# study again as the pipeline test (tests/test_figures_pipeline.cpp) has just run them under ASan,
# then LaTeX, which is not ours to instrument.
sanitize: deps deps-engines
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 -DHERTZDASH_SANITIZE=ON \
	  $(CMAKE_ARGS)
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && \
	  ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1 \
	  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan-suppressions.txt \
	  ctest --output-on-failure -j $(JOBS) -E '^paper_builds$$'

# libFuzzer (clang) on the CSV table, measured-trace, restitution-table, bounce-recording and case-file
# readers, FUZZ_SECONDS each (fuzz/run.sh: seed corpora from data/, fuzz/seeds/ and the docs' case files).
fuzz: deps
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DHERTZDASH_FUZZ=ON \
	  -DHERTZDASH_WITH_MPI=OFF $(CMAKE_ARGS)
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target csv_table_fuzzer measured_trace_fuzzer restitution_table_fuzzer \
	  bounce_recording_fuzzer sweep_case_fuzzer
	fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(FUZZ_BUILD) $(BUILD_TIMES_BUILD)
