#!/usr/bin/env bash
# Regenerate every figure: run each study program, then draw each figure.
#   validation/run_studies.sh BUILD_DIR OUT_DIR [--reduced]
# Study programs are BUILD_DIR/<layer>/<study> (from <layer>/<study>/<study>.cpp, layer
# validation or bench: the work-precision study lives with the peers it times);
# each writes CSV into OUT_DIR and LaTeX fragments into OUT_DIR/../generated. Then every
# gnuplot script <layer>/<study>/<figure>.gp is run as
#   validation/draw_figure.sh <figure>.gp OUT_DIR   (gnuplot -d -c <figure>.gp OUT_DIR, drawn
#                                                    under temporary names, then renamed)
# and writes OUT_DIR/<figure>.pdf and OUT_DIR/<figure>.png from OUT_DIR/<figure>*.csv,
# so restyling a plot never re-runs a simulation. <layer>/<study>/outputs.txt lists
# what each study must produce (checked by tests/test_figures_pipeline.cpp on a
# --reduced run). Every run records its mode (full or reduced), wall time, the date and the machine in
# OUT_DIR/../generated/run_studies.tex for the paper and the README.
set -euo pipefail
usage="usage: run_studies.sh BUILD_DIR OUT_DIR [--reduced]"
build=${1:?$usage}
out=${2:?$usage}
shift 2
reduced=false
for arg in "$@"; do
  case "$arg" in
    --reduced) reduced=true ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
mkdir -p "$out"
generated=$(cd "$out/.." && pwd)/generated
mkdir -p "$generated"
start=$(date +%s.%N)
for dir in "$root"/validation/*/ "$root"/bench/*/; do
  study=$(basename "$dir")
  [ -f "$dir/$study.cpp" ] || continue
  program="$build/$(basename "$(dirname "$dir")")/$study"
  if [ ! -x "$program" ]; then
    echo "run_studies.sh: $program is missing: build first (cmake --build $build)" >&2
    exit 1
  fi
  echo "== study $study"
  "$program" --out "$out" --generated "$generated" "$@"
done
for gp in "$root"/validation/*/*.gp "$root"/bench/*/*.gp; do
  [ -e "$gp" ] || continue
  echo "== figure $(basename "$gp" .gp)"
  "$here/draw_figure.sh" "$gp" "$out"
done
seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3f", b - a }')
printf '== all figures in %s (%.1f s)\n' "$out" "$seconds"
revision=$(git -C "$here" describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1)
tmp="$generated/run_studies.tex.tmp.$$"
{
  echo "% hertzdash validation/run_studies.sh: wall time of one figure run (studies + gnuplot)"
  echo "% git_revision: $revision"
  echo "% build_dir = $build"
  printf '\\newcommand{\\runStudiesSeconds}{%.0f}\n' "$seconds"
  echo "\\newcommand{\\runStudiesMode}{$([ "$reduced" = true ] && echo reduced || echo full)}"
  echo "\\newcommand{\\runStudiesDate}{$(date -u +%Y-%m-%d)}"
  echo "\\newcommand{\\runStudiesCores}{$(nproc)}"
  echo "\\newcommand{\\runStudiesCpu}{${cpu:-unknown CPU}}"
} > "$tmp"
mv "$tmp" "$generated/run_studies.tex"
