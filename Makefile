# hertzdash top-level targets. `make figures` and `make test` are the two
# commands the README promises; both install missing Debian packages first.
BUILD   ?= build
JOBS    ?= $(shell nproc)
FIGURES ?= paper/figures

.PHONY: all deps configure build test figures convergence clean

all: build

deps:
	@tools/install-deps.sh debian-packages.txt

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

clean:
	rm -rf $(BUILD)
