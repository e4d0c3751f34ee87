# hertzdash top-level targets. `make figures` and `make test` are the two
# commands the README promises; both install missing Debian packages first.
BUILD   ?= build
JOBS    ?= $(shell nproc)
FIGURES ?= paper/figures

.PHONY: all deps configure build test figures bench clean

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

# Work precision against Boost.Odeint, GSL and CVODE at full repeats (a few minutes):
# prints the table and ratios, writes the CSVs the figure is drawn from, the paper's
# \perf macros, and the measured block of the README.
# It first times `make figures` from the built tree (into a scratch directory).
bench: build
	@start=$$(date +%s%N); \
	validation/run_studies.sh $(BUILD) $(BUILD)/figures-timing > /dev/null; \
	ms=$$(( ($$(date +%s%N) - start) / 1000000 )); \
	$(BUILD)/bench/hertzdash_bench --out $(FIGURES) --generated paper/generated --readme README.md \
	  --figures-ms $$ms
	gnuplot -d -c validation/work_precision_peers/work_precision_peers.gp $(FIGURES)

clean:
	rm -rf $(BUILD)
