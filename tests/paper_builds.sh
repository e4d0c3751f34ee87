#!/usr/bin/env bash
# ctest paper_builds: the article builds from a fresh, reduced run of every study,
# and the checks of paper/build.sh catch what they promise to catch.
#   tests/paper_builds.sh BUILD_DIR SOURCE_DIR
# 1. Run validation/run_studies.sh --reduced into an empty temporary tree beside a copy
#    of the article's sources (paper.tex, references.tex, sections/), so nothing left in
#    the source tree's paper/generated or paper/figures can stand in for a missing
#    output, and build the article there with paper/build.sh (which fails on LaTeX
#    errors, undefined references, margin overruns, '??' in the text, sentences joined
#    without a space, bitmap fonts, unused outputs).
# 2. Break the tree in five ways, one at a time, and require paper/build.sh to fail:
#    a generated macro file removed, a reference to a label that does not exist, a
#    figure that the article does not include, a "??" in the text, and a sentence run
#    into the next without a space (a % after a full stop).
set -euo pipefail
build=${1:?usage: paper_builds.sh BUILD_DIR SOURCE_DIR}
src=${2:?usage: paper_builds.sh BUILD_DIR SOURCE_DIR}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

fresh_tree() {  # fresh_tree DIR: the article's sources beside the outputs of step 1
  mkdir -p "$1"
  cp "$src/paper/paper.tex" "$src/paper/references.tex" "$1/"
  cp -r "$src/paper/sections" "$1/"
  [ "$1" = "$tmp/paper" ] || cp -r "$tmp/paper/figures" "$tmp/paper/generated" "$1/"
}

# 1. The real thing.
fresh_tree "$tmp/paper"
"$src/validation/run_studies.sh" "$build" "$tmp/paper/figures" --reduced
"$src/paper/build.sh" "$tmp/paper"

# 2. Each defect must fail the build, with the reason named.
expect_failure() {  # expect_failure NAME PATTERN: build $tmp/NAME, require failure naming PATTERN
  local out
  if out=$("$src/paper/build.sh" "$tmp/$1" 2>&1); then
    echo "paper_builds: the build of a tree with '$1' succeeded; paper/build.sh misses that defect" >&2
    exit 1
  fi
  if ! grep -q -- "$2" <<<"$out"; then
    echo "paper_builds: '$1' failed without naming '$2':" >&2
    echo "$out" >&2
    exit 1
  fi
  echo "paper_builds: '$1' fails as it should"
}

fresh_tree "$tmp/missing_generated"
rm "$tmp/missing_generated/generated/paper_numbers.tex"
expect_failure missing_generated "paper_numbers.tex"

fresh_tree "$tmp/undefined_reference"
echo '\ref{sec:no-such-section}' >>"$tmp/undefined_reference/sections/conclusions.tex"
expect_failure undefined_reference "sec:no-such-section"

fresh_tree "$tmp/unused_figure"
cp "$tmp/paper/paper.pdf" "$tmp/unused_figure/figures/not_in_the_article.pdf"
expect_failure unused_figure "figures/not_in_the_article.pdf"

fresh_tree "$tmp/question_marks"
echo 'A reference typed by hand as ?? stays unresolved.' >>"$tmp/question_marks/sections/conclusions.tex"
expect_failure question_marks "'??' in the text"

fresh_tree "$tmp/joined_sentence"
printf '%s\n' 'One sentence ends here.%' ' Another starts without a space.' >>"$tmp/joined_sentence/sections/conclusions.tex"
expect_failure joined_sentence "here.Another"
