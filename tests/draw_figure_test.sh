#!/usr/bin/env bash
# validation/draw_figure.sh: a figure is replaced only by a complete one (docs/output-files.md).
#   tests/draw_figure_test.sh SOURCE_DIR
# 1. a script that succeeds replaces the previous PNG with a real one (PNG signature);
# 2. a script that fails after its plot leaves the previous PNG and no temporary;
# 3. SIGTERM while gnuplot is drawing (a pause after the output is opened) leaves the previous
#    PNG and no temporary, and ends the wrapper with 143.
# 4. SIGTERM to the wrapper while a gnuplot that writes its output on the way out (a stand-in
#    on PATH: it recreates the temporary 0.5 s after SIGTERM) runs: the wrapper waits for it to
#    exit before removing the temporaries, so none is left. Before, the wrapper removed them at
#    once and the late write left one behind.
# 5. a script whose data file is missing (gnuplot only warns and draws an empty plot) fails with
#    exit 1 naming the cause, and leaves the previous PNG and no temporary.
# Before the wrapper, gnuplot wrote OUT/fig.png in place: cases 2 and 3 left a new or empty file.
set -uo pipefail
source_dir=${1:?usage: draw_figure_test.sh SOURCE_DIR}
draw="$source_dir/validation/draw_figure.sh"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

write_script() {  # NAME, then gnuplot lines after the output is set (in a loop over formats,
  local name=$1    # as the figure scripts do: output.gnuplot runs inside brackets)
  shift
  {
    echo "do for [format in 'png'] {"
    echo "  call '$source_dir/validation/output.gnuplot' ARG1.'/fig' format 2.0 1.5"
    printf '  %s\n' "$@"
    echo "}"
  } > "$scratch/$name.gp"
}
previous() { printf 'previous figure\n' > "$scratch/out/fig.png"; }
check_previous_kept() {  # CASE
  printf 'previous figure\n' | cmp -s - "$scratch/out/fig.png" || fail "$1: the previous figure was replaced"
  local left
  left=$(find "$scratch/out" -name '*.tmp.*' | wc -l)
  [ "$left" -eq 0 ] || fail "$1: $left temporaries left"
}

mkdir -p "$scratch/out"
write_script good "plot x"
write_script bad "plot x" "this_is_not_a_command"
write_script slow "plot x" "pause 30"
write_script missing "plot '$scratch/no_such_file.csv' using 1:2"

previous
"$draw" "$scratch/good.gp" "$scratch/out" || fail "good: exit $?"
[ "$(head -c 4 "$scratch/out/fig.png" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "good: fig.png is not a PNG"

previous
"$draw" "$scratch/bad.gp" "$scratch/out" 2>/dev/null && fail "bad: exit 0"
check_previous_kept bad

previous
"$draw" "$scratch/missing.gp" "$scratch/out" 2> "$scratch/missing.err"
status=$?
[ "$status" -eq 1 ] || fail "missing data: exit $status, not 1"
grep -q "reads a data file that does not exist" "$scratch/missing.err" || fail "missing data: the cause is not named"
check_previous_kept "missing data"

previous
"$draw" "$scratch/slow.gp" "$scratch/out" &
pid=$!
for _ in $(seq 200); do  # until gnuplot has opened its temporary output (at most 20 s)
  [ -n "$(find "$scratch/out" -name 'fig.png.tmp.*')" ] && break
  sleep 0.1
done
[ -n "$(find "$scratch/out" -name 'fig.png.tmp.*')" ] || fail "slow: no temporary output appeared"
kill -TERM "$pid"
wait "$pid"
status=$?
[ "$status" -eq 143 ] || fail "slow: exit $status, not 143"
check_previous_kept slow

mkdir -p "$scratch/bin"
cat > "$scratch/bin/gnuplot" <<'FAKE'
#!/usr/bin/env bash
# Called as: gnuplot -d -e "figure_suffix='SUFFIX'" -c SCRIPT OUT_DIR
suffix=${3#figure_suffix=\'}
suffix=${suffix%\'}
tmp="$6/fig.png$suffix"
printf 'partial' > "$tmp"
trap 'kill "$sleeper" 2>/dev/null; sleep 0.5; printf "late" > "$tmp"; exit 1' TERM
sleep 30 &
sleeper=$!
wait "$sleeper"
FAKE
chmod +x "$scratch/bin/gnuplot"
previous
PATH="$scratch/bin:$PATH" "$draw" "$scratch/good.gp" "$scratch/out" &
pid=$!
for _ in $(seq 200); do
  [ -n "$(find "$scratch/out" -name 'fig.png.tmp.*')" ] && break
  sleep 0.1
done
kill -TERM "$pid"
wait "$pid"
status=$?
[ "$status" -eq 143 ] || fail "late writer: exit $status, not 143"
sleep 1  # a stand-in that was not waited for writes within 0.5 s
check_previous_kept "late writer"

[ "$failures" -eq 0 ] && echo "draw_figure.sh: all checks passed"
exit $((failures > 0))
