#!/usr/bin/env bash
# `make build-times`: how long a law author waits. Configures a scratch build directory with
# ccache disabled, times the cold build (`cmake --build -j JOBS`), touches one damping law's header,
# times the rebuild, then the whole test suite on that built tree (`ctest -j JOBS`, what `make test`
# runs once built; the article's build needs debian-packages-paper.txt), and writes the three, with
# the machine's cores, the load average around each and
# the git revision, into the generated blocks of docs/build-times.md (the table and the files the
# rebuild compiled) and of README.md (one sentence beside the opening commands).
#   tools/measure-build-times.sh [BUILD_DIR [JOBS]]   (default: build-times, nproc)
# LAW_HEADER chooses the header touched (default model/damping/laws/hunt_crossley.hpp). The
# scratch directory is removed first and kept afterwards (its logs: configure.log, cold.log,
# rebuild.log, ctest.log).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-times}
jobs=${2:-$(nproc)}
law=${LAW_HEADER:-model/damping/laws/hunt_crossley.hpp}
[ -f "$law" ] || { echo "measure-build-times.sh: no $law" >&2; exit 2; }
export CCACHE_DISABLE=1  # a cache hit would time nothing

load() { cut -d' ' -f1 /proc/loadavg; }
# Runs "$@" with its output in the log $1; prints the wall time in whole seconds.
timed() {
  local log=$1 start
  shift
  start=$(date +%s.%N)
  "$@" > "$log" 2>&1 || { echo "measure-build-times.sh: failed, see $log" >&2; tail -20 "$log" >&2; exit 1; }
  echo "$(date +%s.%N) $start" | awk '{ printf "%.0f\n", $1 - $2 }'
}
# 1843 -> "30 min 43 s", 42 -> "42 s".
duration() { awk -v s="$1" 'BEGIN { if (s >= 60) printf "%d min %d s\n", s / 60, s % 60; else printf "%d s\n", s }'; }

rm -rf "$build"
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build/configure.log" 2>&1 ||
  { echo "measure-build-times.sh: configuration failed, see $build/configure.log" >&2; exit 1; }
cold_load_start=$(load)
cold_s=$(timed "$build/cold.log" cmake --build "$build" -j "$jobs")
cold_load_end=$(load)
touch "$law"
rebuild_load_start=$(load)
rebuild_s=$(timed "$build/rebuild.log" cmake --build "$build" -j "$jobs")
rebuild_load_end=$(load)
ctest_load_start=$(load)
ctest_s=$(cd "$build" && timed ctest.log ctest -j "$jobs")
ctest_load_end=$(load)
# The slowest tests, from ctest's lines "N/M Test #K: name ....   Passed   12.34 sec".
slowest=$(sed -n 's/.*Test *#[0-9]*: \(.*[^. ]\) *\.\.*  *Passed *\([0-9.]*\) sec$/\2|\1/p' "$build/ctest.log" |
  sort -t'|' -k1,1 -rn | head -5)
# Source paths from make's object names; a generated unit is named by its place in the build directory.
compiled=$(sed -n 's/.*Building CXX object \(.*\)\.o$/\1/p' "$build/rebuild.log" |
  sed 's|CMakeFiles/[^/]*\.dir/||; s|^.*/__/__/generated/|BUILD/generated/|')
compiled_count=$(printf '%s\n' "$compiled" | grep -c . || true)

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
cores=$(nproc)
revision=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- . ':!docs/build-times.md' ':!README.md' 2>/dev/null || revision="$revision (modified)"

page=$(mktemp)
sentence=$(mktemp)
trap 'rm -f "$page" "$sentence"' EXIT
{
  echo "Measured on ${cpu:-an unknown CPU} ($cores cores), git $revision, \`make build-times\` with ccache"
  echo "disabled, \`cmake --build -j $jobs\`; the load average (1 min) before and after each build says how"
  echo "busy the machine was:"
  echo
  echo "| build | wall time | load before | load after |"
  echo "|---|---|---|---|"
  echo "| cold (a fresh build directory: libraries, program, studies, benchmark, tests) | $(duration "$cold_s") | $cold_load_start | $cold_load_end |"
  echo "| after \`touch $law\` | $(duration "$rebuild_s") | $rebuild_load_start | $rebuild_load_end |"
  echo "| the test suite on the built tree (\`ctest -j $jobs\`, as \`make test\`) | $(duration "$ctest_s") | $ctest_load_start | $ctest_load_end |"
  echo
  echo "The slowest tests (seconds each, run $jobs at a time):"
  echo
  printf '%s\n' "$slowest" | awk -F'|' '{ printf "- `%s`: %.0f s\n", $2, $1 }'
  echo
  echo "The rebuild compiled $compiled_count files:"
  echo
  printf '%s\n' "$compiled" | sed 's/^/- `/; s/$/`/'
} > "$page"
echo "Cold build: $(duration "$cold_s") on $cores cores (load $cold_load_start); $(duration "$rebuild_s") after editing one law ([docs/build-times.md](docs/build-times.md))." > "$sentence"

# Replaces the lines between "<!-- NAME:begin" and "<!-- NAME:end -->" of FILE by those of BODY.
replace_block() {
  local file=$1 name=$2 body=$3
  grep -q "^<!-- $name:begin" "$file" && grep -q "^<!-- $name:end -->" "$file" ||
    { echo "measure-build-times.sh: $file has no $name:begin/end block" >&2; exit 1; }
  awk -v begin="<!-- $name:begin" -v end="<!-- $name:end -->" -v body="$body" '
    index($0, begin) == 1 { print; while ((getline line < body) > 0) print line; skip = 1; next }
    index($0, end) == 1 { skip = 0 }
    !skip { print }' "$file" > "$file.tmp"
  mv "$file.tmp" "$file"
}
replace_block docs/build-times.md build-times "$page"
replace_block README.md build-times "$sentence"
echo "cold build $(duration "$cold_s"), rebuild after touching $law $(duration "$rebuild_s") ($compiled_count files),"
echo "the test suite $(duration "$ctest_s");"
echo "written to docs/build-times.md and README.md"
