#!/usr/bin/env bash
# Regenerate every figure: run each study program, then draw each figure.
#   validation/run_studies.sh BUILD_DIR OUT_DIR [--reduced]
# Study programs are build/validation/<study> (from validation/<study>/<study>.cpp);
# each writes CSV (+ LaTeX fragments) into OUT_DIR. Then every gnuplot script
# validation/<study>/<figure>.gp is run as
#   gnuplot -d -c <figure>.gp OUT_DIR
# and writes OUT_DIR/<figure>.pdf and OUT_DIR/<figure>.png from OUT_DIR/<figure>*.csv,
# so restyling a plot never re-runs a simulation.
set -euo pipefail
build=${1:?usage: run_studies.sh BUILD_DIR OUT_DIR [--reduced]}
out=${2:?usage: run_studies.sh BUILD_DIR OUT_DIR [--reduced]}
shift 2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
start=$(date +%s)
for dir in "$here"/*/; do
  study=$(basename "$dir")
  [ -f "$dir/$study.cpp" ] || continue
  echo "== study $study"
  "$build/validation/$study" --out "$out" "$@"
done
for gp in "$here"/*/*.gp; do
  [ -e "$gp" ] || continue
  echo "== figure $(basename "$gp" .gp)"
  gnuplot -d -c "$gp" "$out"
done
echo "== all figures in $out ($(( $(date +%s) - start )) s)"
