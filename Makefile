# hertzdash top-level targets. `make figures` and `make test` are the two
# commands the README promises; both install missing Debian packages first.
BUILD   ?= build
JOBS    ?= $(shell nproc)
FIGURES ?= paper/figures

.PHONY: all deps configure build test figures convergence uncertainty paper bench clean

all: build

# TeX is in the test dependencies: the test suite builds the paper.
deps:
	@tools/install-deps.sh debian-packages.txt debian-packages-paper.txt

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

figures: build
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

# The article: every study and figure, then latexmk in paper/. The date in the PDF
# is the last commit's (SOURCE_DATE_EPOCH), so the same commit gives the same PDF.
paper: figures
	@epoch=$$(git log -1 --format=%ct 2>/dev/null); \
	if [ -n "$$epoch" ]; then export SOURCE_DATE_EPOCH=$$epoch FORCE_SOURCE_DATE=1; fi; \
	paper/build.sh paper

# Work precision against Boost.Odeint, GSL and CVODE at full repeats (a few minutes):
# prints the table and ratios, writes the CSVs the figure is drawn from, the paper's
# \perf macros, and the measured blocks of docs/performance.md and README.md.
# It first times `make figures` from the built tree (into a scratch directory).
bench: build
	@start=$$(date +%s%N); \
	validation/run_studies.sh $(BUILD) $(BUILD)/figures-timing > /dev/null; \
	ms=$$(( ($$(date +%s%N) - start) / 1000000 )); \
	$(BUILD)/bench/work_precision_peers --full --out $(FIGURES) --generated paper/generated --performance-page docs/performance.md \
	  --performance-page README.md --figures-ms $$ms
	validation/draw_figure.sh bench/work_precision_peers/work_precision_peers.gp $(FIGURES)

clean:
	rm -rf $(BUILD)
