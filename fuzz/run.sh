#!/usr/bin/env bash
# Run each libFuzzer harness for a bounded time (make fuzz; docs/reliability.md):
#   fuzz/run.sh FUZZ_BUILD_DIR [SECONDS]     (SECONDS: each harness, default $FUZZ_SECONDS or 60)
# Seed corpora: the CSV tables of data/ (CSV reader), the seeds of fuzz/seeds/ (all five), the
# TOML blocks of README.md and docs/sweep.md (case files). Each harness keeps its corpus in
# FUZZ_BUILD_DIR/corpus/NAME (it grows from run to run) and writes any finding to
# FUZZ_BUILD_DIR/findings/NAME/; the script fails on the first finding, which must then become a
# regression test in tests/.
set -euo pipefail
usage="usage: fuzz/run.sh FUZZ_BUILD_DIR [SECONDS]"
build=${1:?$usage}
seconds=${2:-${FUZZ_SECONDS:-60}}
root=$(cd "$(dirname "$0")/.." && pwd)

seed() {  # NAME: fill the corpus folder with the seeds (content-named, so repeats are one file)
  local name=$1 dir="$build/corpus/$1"
  mkdir -p "$dir"
  cp "$root"/fuzz/seeds/"$name"/* "$dir"/
  case "$name" in
    csv_table) cp "$root"/data/*.csv "$root"/data/external/*/*.csv "$dir"/ ;;
    measured_trace | restitution_table | bounce_recording) ;;
    sweep_case)
      for doc in README.md docs/sweep.md; do
        awk -v out="$dir/$(basename "$doc" .md)_" '/^```toml$/ {n++; inside = 1; next} /^```$/ {inside = 0}
             inside {print > (out n ".toml")}' "$root/$doc"
      done ;;
  esac
}

status=0
for name in csv_table measured_trace restitution_table bounce_recording sweep_case; do
  seed "$name"
  mkdir -p "$build/findings/$name"
  echo "== fuzz $name: ${seconds} s, corpus $(ls "$build/corpus/$name" | wc -l) files"
  # -timeout: one input taking over 10 s is a finding (a hang); -rss_limit_mb: over 2 GiB is one.
  if ! "$build/fuzz/${name}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$build/findings/$name/" -print_final_stats=1 "$build/corpus/$name" \
      > "$build/findings/$name.log" 2>&1; then
    echo "fuzz/run.sh: $name found a defect; its input is in $build/findings/$name/:" >&2
    grep -E "ERROR|SUMMARY|==[0-9]+==|runtime error|terminate" "$build/findings/$name.log" | head -n 20 >&2
    status=1
  fi
  grep -E "^stat::number_of_executed_units|^#[0-9]+.*DONE" "$build/findings/$name.log" | tail -n 2
done
exit "$status"
