#!/usr/bin/env bash
# `mpirun -n 2 hertzdash shaker --sweep` writes the same diagram as the threaded run, byte for
# byte (docs/shaker.md): the values go round-robin to the ranks and rank 0 gathers their impacts
# and warnings. The sweep starts at gamma 0.9, where the wall never pulls away from the body (a
# run with no impact and a warning), so the gather of empty runs and of warnings is exercised.
# Usage: shaker_sweep_mpi.sh HERTZDASH_BIN MPIEXEC
set -euo pipefail
bin=$1
mpiexec=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
args=(shaker --restitution 0.5 --sweep gamma:0.9:1.8:10 --impacts 8 --transient 300)
"$bin" "${args[@]}" --csv threads.csv --threads 2 > threads.out 2> threads.err || { cat threads.err; exit 1; }
# Open MPI refuses root without these; --oversubscribe allows 2 ranks on any machine.
# Under `make sanitize`, Open MPI's plugins are dlopen'd and unloaded before LeakSanitizer reports,
# so their leaks show as "<unknown module>", which no suppression (tests/lsan-suppressions.txt)
# can name: leak checking is off for the MPI run only. Our code's leaks are checked by the
# threaded run of the same sweep above, which runs every line the ranks run but the gather.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
  "$mpiexec" -n 2 "$bin" "${args[@]}" --csv mpi.csv > mpi.out 2> mpi.err || { cat mpi.err; exit 1; }
grep -q 'on 2 processes x ' mpi.out || { echo "MPI did not start 2 processes"; cat mpi.out mpi.err; exit 1; }
grep -q '^# warning, run 0: ' mpi.csv || { echo "the warning of run 0 (gamma 0.9) is missing"; exit 1; }
cmp threads.csv mpi.csv
rows=$(grep -vc '^#' mpi.csv)
[ "$rows" -eq 73 ] || { echo "expected 72 rows (9 values of 8 impacts) and the column names, got $rows lines"; exit 1; }
# The general sweep: a case file with rig = "shaker" over the same gamma (simulation/sweep/
# sweep_case.hpp), its rows and its per-impact tables the same on 2 processes as on 2 threads.
cat > case.toml <<'CASE'
[base]
rig = "shaker"
restitution = 0.5
impacts = 8
transient = 300
[grid]
gamma = { from = 0.9, to = 1.8, count = 10 }
CASE
"$bin" sweep case.toml --out rig-threads.csv --threads 2 --quiet > /dev/null 2> rig-threads.err || { cat rig-threads.err; exit 1; }
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
  "$mpiexec" -n 2 "$bin" sweep case.toml --out rig-mpi.csv --quiet > /dev/null 2> rig-mpi.err || { cat rig-mpi.err; exit 1; }
grep -q '^# timing: .* on 2 processes x ' rig-mpi.csv || { echo "MPI did not start 2 processes"; exit 1; }
diff <(grep -v '^# timing:' rig-threads.csv) <(grep -v '^# timing:' rig-mpi.csv)
cmp rig-threads.impacts.csv rig-mpi.impacts.csv
[ "$(grep -vc '^#' rig-mpi.impacts.csv)" -eq 73 ] || { echo "expected the diagram's 72 impacts in the rig's table"; exit 1; }
echo "mpirun -n 2 and 2 threads wrote the same diagram, and the same rig case file"
