#!/usr/bin/env bash
# Draw one figure script so that a failure or a kill never leaves a partial or empty figure in
# place of the previous one (docs/output-files.md):
#   validation/draw_figure.sh SCRIPT.gp OUT_DIR
# gnuplot writes in place, so output.gnuplot appends figure_suffix (set here to .tmp.PID) to
# every output name; once the whole script has succeeded, each OUT_DIR/NAME.EXT.tmp.PID is
# renamed over OUT_DIR/NAME.EXT. On failure, SIGINT, SIGTERM or SIGHUP the temporaries are
# removed and the previous figures stay. A data file the script cannot open is a failure (gnuplot
# itself only warns and draws an empty plot): exit 1, the previous figures stay.
set -euo pipefail
usage="usage: draw_figure.sh SCRIPT.gp OUT_DIR"
script=${1:?$usage}
out=${2:?$usage}
[ $# -eq 2 ] || { echo "$usage" >&2; exit 2; }
suffix=".tmp.$$"
gnuplot_pid=
messages=$(mktemp)  # gnuplot's stderr, shown once it has exited
# gnuplot may still create or write a temporary after the signal (it finishes its output on
# exit), so the temporaries are removed only once it has exited: after SIGTERM, up to 5 s, then
# SIGKILL.
cleanup() {
  if [ -n "$gnuplot_pid" ]; then
    kill "$gnuplot_pid" 2>/dev/null || true
    for _ in $(seq 50); do
      kill -0 "$gnuplot_pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -KILL "$gnuplot_pid" 2>/dev/null || true
    wait "$gnuplot_pid" 2>/dev/null || true
  fi
  rm -f -- "$out"/*"$suffix"
  cat "$messages" >&2
  rm -f -- "$messages"
}
trap cleanup EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM
# In the background and waited for, so that a signal is handled at once, not after gnuplot.
gnuplot -d -e "figure_suffix='$suffix'" -c "$script" "$out" 2> "$messages" &
gnuplot_pid=$!
status=0
wait "$gnuplot_pid" || status=$?
gnuplot_pid=
if grep -q "Cannot find or open file" "$messages"; then
  echo "draw_figure.sh: $script reads a data file that does not exist (above); no figure replaced" >> "$messages"
  exit 1
fi
[ "$status" -eq 0 ] || exit "$status"
for tmp in "$out"/*"$suffix"; do
  [ -e "$tmp" ] || continue
  mv -f -- "$tmp" "${tmp%"$suffix"}"
done
