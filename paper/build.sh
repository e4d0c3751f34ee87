#!/usr/bin/env bash
# Typeset the article and check it: paper/build.sh PAPER_DIR
#
# PAPER_DIR holds paper.tex, references.tex and sections/ (the sources) beside
# generated/ and figures/ (what `make figures` or run_studies.sh wrote). Runs latexmk
# with pdfLaTeX, stopping at the first error, then reads the log and fails on
#   - any LaTeX error (latexmk's status),
#   - undefined references or citations, or labels that changed on the last run,
#   - overfull boxes wider than 5 pt (text running into the margin; up to 5 pt is
#     invisible at print size and microtype leaves a few of those),
#   - "??" in the PDF's text (pdftotext): a reference or citation LaTeX could not resolve,
#     whatever the log says,
#   - a sentence run into the next without a space, "[a-z)].[A-Z][a-z]" in the PDF's text
#     (e.g. "the step.Nor", left by a % after a full stop); names with a dot inside are
#     listed in $sentence_allow below (now: Boost.Odeint). Abbreviations ("e.g.", "Fig.~5")
#     are followed by a space, a digit or lower case, so the pattern does not see them,
#   - bitmap (Type 3) fonts from TeX, which blur when zoomed: a symbol from the TS1
#     text companion such as \textmu; use the math-mode symbol instead,
#   - a figure in figures/*.pdf or a fragment in generated/*.tex that the article
#     never reads (every output of the suite belongs in the article).
# For a reproducible PDF set SOURCE_DATE_EPOCH (and FORCE_SOURCE_DATE=1) first;
# `make paper` does.
set -euo pipefail
dir=${1:?usage: paper/build.sh PAPER_DIR}
cd "$dir"
for need in generated figures; do
  [ -d "$need" ] || { echo "paper: $dir/$need is missing: run 'make figures' first" >&2; exit 1; }
done

status=0
# -g: always run, since latexmk cannot see a section file appear (\IfFileExists of a
# missing file leaves no dependency behind).
latexmk -g -pdf -recorder -halt-on-error -interaction=nonstopmode -file-line-error paper.tex >latexmk.log 2>&1 || status=$?
if [ $status -ne 0 ]; then
  echo "paper: latexmk failed (status $status); the first error in $dir/paper.log:" >&2
  grep -m1 -A6 -E '^(\./|/)?[^:]*:[0-9]+: |^! ' paper.log >&2 || tail -20 latexmk.log >&2
  exit 1
fi

problems=$(grep -E "LaTeX Warning: (Reference|Citation) .* undefined|There were undefined references|Label\(s\) may have changed|LaTeX Warning: There were multiply-defined labels" paper.log || true)
overfull=$(grep -E '^Overfull \\hbox \(([5-9]|[1-9][0-9]+)\.[0-9]+pt too wide\)' -A1 paper.log || true)

# Every figure and generated fragment must be read by the article (-recorder lists
# every file TeX opened in paper.fls).
unused=""
for f in figures/*.pdf generated/*.tex; do
  [ -e "$f" ] || continue
  grep -qE "^INPUT (\./)?$f\$" paper.fls || unused+=" $f"
done

# The PDF's text: unresolved "??" and sentences joined without a space. pdftotext joins
# a hyphenated line end to the next line's start, which cannot produce either pattern.
# sentence_allow: a regular expression of names with a dot inside that are no sentence end.
sentence_allow='Boost\.Odeint'
pdftotext -enc UTF-8 paper.pdf paper.txt
unresolved=$(grep -n -F '??' paper.txt || true)
joined=$(sed -E "s/$sentence_allow/(allowed)/g" paper.txt | grep -n -oE '.{0,30}[a-z)]\.[A-Z][a-z].{0,10}' || true)

# pdffonts names TeX's bitmap fonts "[none]", Type 3.
bitmap_fonts=$(pdffonts paper.pdf | grep -cE '^\[none\] +Type 3' || true)

fail=0
if [ -n "$problems" ]; then echo "paper: unresolved references:" >&2; echo "$problems" >&2; fail=1; fi
if [ -n "$overfull" ]; then echo "paper: lines running into the margin:" >&2; echo "$overfull" >&2; fail=1; fi
if [ -n "$unresolved" ]; then echo "paper: '??' in the text of paper.pdf (line of paper.txt: text):" >&2; echo "$unresolved" >&2; fail=1; fi
if [ -n "$joined" ]; then echo "paper: a sentence ends without a space before the next (line of paper.txt: text):" >&2; echo "$joined" >&2; fail=1; fi
if [ "$bitmap_fonts" -gt 0 ]; then
  echo "paper: $bitmap_fonts bitmap font(s) in paper.pdf: a TS1 text symbol (e.g. \\textmu, \\textbullet); use math mode" >&2
  fail=1
fi
if [ -n "$unused" ]; then echo "paper: outputs the article never uses:$unused" >&2; fail=1; fi
[ $fail -eq 0 ] || exit 1
pages=$(grep -oE 'Output written on paper.pdf \(([0-9]+) pages' paper.log | grep -oE '[0-9]+ pages' || echo "? pages")
echo "paper: $dir/paper.pdf ($pages)"
