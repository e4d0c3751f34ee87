#!/usr/bin/env bash
# Compare two runs of `make figures` (or validation/run_studies.sh) number by number:
#   tools/compare-generated.sh OLD_DIR NEW_DIR
# OLD_DIR and NEW_DIR each hold figures/ and generated/ (e.g. paper/ of two checkouts).
# Every CSV, LaTeX and Markdown file is compared without its comment lines (# or %:
# the provenance header, which names the git revision) and without the columns and
# macros that are wall times (machine- and load-dependent): cpu_time_s, us_per_impact,
# the \perf... and \runStudies... macros, and the whole work_precision_peers_table.tex (a
# table of timings). The git revision itself is ignored, and so is the order of a CSV's
# rows (compared sorted). Prints one
# line per file that differs and exits 1 if any does; a refactoring that should leave
# every result alone must print nothing.
set -euo pipefail
old=${1:?usage: compare-generated.sh OLD_DIR NEW_DIR}
new=${2:?usage: compare-generated.sh OLD_DIR NEW_DIR}

# The file without comments, timing columns and revision lines.
numbers() {
  local f=$1
  case "$f" in
    *.csv)
      grep -v '^#' "$f" | awk -F, '
        NR == 1 { for (i = 1; i <= NF; ++i) keep[i] = ($i != "cpu_time_s" && $i != "us_per_impact") }
        { line = ""; for (i = 1; i <= NF; ++i) if (keep[i]) line = line $i ","; print line }' |
        grep -v '^git_revision,' | { IFS= read -r header; printf '%s\n' "$header"; LC_ALL=C sort; } ;;
    *)
      grep -v '^%' "$f" | grep -v -e '\\perf' -e '\\runStudies' -e 'git_revision' -e 'GitRevision' || true ;;
  esac
}

status=0
while IFS= read -r rel; do
  if [ ! -f "$new/$rel" ]; then
    echo "missing in $new: $rel"; status=1; continue
  fi
  if ! cmp -s <(numbers "$old/$rel") <(numbers "$new/$rel"); then
    echo "differs: $rel ($(diff <(numbers "$old/$rel") <(numbers "$new/$rel") | grep -c '^<') lines)"; status=1
  fi
done < <(cd "$old" && find . \( -name '*.csv' -o -name '*.tex' -o -name '*.md' \) ! -name work_precision_peers_table.tex |
         sed 's|^\./||' | sort)
while IFS= read -r rel; do
  [ -f "$old/$rel" ] || { echo "new in $new: $rel"; status=1; }
done < <(cd "$new" && find . \( -name '*.csv' -o -name '*.tex' -o -name '*.md' \) | sed 's|^\./||' | sort)
exit $status
