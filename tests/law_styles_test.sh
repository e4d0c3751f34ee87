#!/usr/bin/env bash
# Every registered damping law is drawn in a style of its own: the (colour, dash, width) that
# validation/damping_laws/law_styles.gnuplot gives each law `hertzdash models` lists differs
# from every other law's. Before, the styles cycled eleven colours by order of appearance, so a
# 15th law took the colour of the 4th and one law changed colour between figures.
#   tests/law_styles_test.sh HERTZDASH SOURCE_DIR [EXTRA_LAW...]
# EXTRA_LAW names stand for laws not yet in the table (the test of the test: two of them share
# the fall-back style and must fail).
set -euo pipefail
hertzdash=${1:?usage: law_styles_test.sh HERTZDASH SOURCE_DIR [EXTRA_LAW...]}
src=${2:?usage: law_styles_test.sh HERTZDASH SOURCE_DIR [EXTRA_LAW...]}
shift 2
names=$("$hertzdash" models --json | python3 -c 'import json, sys; print(" ".join(m["name"] for m in json.load(sys.stdin)))')
names="$names $*"
[ "$(wc -w <<< "$names")" -ge 14 ] || { echo "FAIL: only $(wc -w <<< "$names") laws listed: $names" >&2; exit 1; }
styles=$(gnuplot -e "load '$src/validation/damping_laws/law_styles.gnuplot'; do for [n in '$names'] { print sprintf('%s %s %d %.2f', n, law_lc(n), law_dt(n), law_lw(n)) }" 2>&1)
echo "$styles"
shared=$(awk '{ style = $2 " " $3 " " $4; if (style in owner) print owner[style] " and " $1 " share " style; else owner[style] = $1 }' <<< "$styles")
if [ -n "$shared" ]; then echo "FAIL: $shared" >&2; exit 1; fi
echo "law_styles: $(wc -l <<< "$styles") laws, each in a style of its own"
