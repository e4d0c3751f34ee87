#!/usr/bin/env bash
# Determinism: every study that runs its impacts in parallel (its source calls parallel_sweep or
# parallel_for_chunks) writes the same files, byte for byte, on 1 thread and on 3
# (HERTZDASH_THREADS; reduced runs), apart from timing and provenance lines (none differ
# today; the filter is there so that a wall time or a date in a header would not fail it).
#   tests/study_threads.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=${1:?usage: study_threads.sh BUILD_DIR SOURCE_DIR}
source_dir=${2:?usage: study_threads.sh BUILD_DIR SOURCE_DIR}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
studies=()
for cpp in "$source_dir"/validation/*/*.cpp; do
  study=$(basename "$cpp" .cpp)
  [ "$study" = "$(basename "$(dirname "$cpp")")" ] || continue
  grep -qE 'parallel_sweep|parallel_for_chunks' "$cpp" && studies+=("$study")
done
[ "${#studies[@]}" -ge 3 ] || { echo "FAIL: found only ${#studies[@]} parallel studies: ${studies[*]}" >&2; exit 1; }
for threads in 1 3; do
  for study in "${studies[@]}"; do
    HERTZDASH_THREADS=$threads "$build/validation/$study" --out "$scratch/t$threads/figures" \
      --generated "$scratch/t$threads/generated" --reduced > "$scratch/$study.$threads.log" 2>&1 ||
      { echo "FAIL: $study on $threads threads:" >&2; cat "$scratch/$study.$threads.log" >&2; exit 1; }
  done
done
strip() { grep -v -E '^(#|%) ?(git_revision|timing|generated_at|date)\b' "$1" || true; }
failures=0 files=0
for one in $(cd "$scratch/t1" && find . -type f | sort); do
  files=$((files + 1))
  three="$scratch/t3/$one"
  if [ ! -f "$three" ]; then echo "FAIL: $one written on 1 thread only" >&2; failures=$((failures + 1)); continue; fi
  if ! diff <(strip "$scratch/t1/$one") <(strip "$three") > "$scratch/diff" 2>&1; then
    echo "FAIL: $one differs between 1 and 3 threads:" >&2
    head -n 10 "$scratch/diff" >&2
    failures=$((failures + 1))
  fi
done
[ "$(cd "$scratch/t3" && find . -type f | wc -l)" -eq "$files" ] || { echo "FAIL: 3 threads wrote other files" >&2; exit 1; }
echo "studies ${studies[*]}: $files files identical on 1 and 3 threads"
exit $((failures > 0))
