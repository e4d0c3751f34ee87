#!/usr/bin/env bash
# A rig's sweep (a case file with rig = "shaker", the bifurcation diagram of docs/shaker.md) under
# `mpirun -n 2` writes the same rows and per-impact table as on 2 threads, byte for byte but for
# the timing line: the runs go round-robin to the ranks and rank 0 gathers their impacts and
# warnings. The sweep starts at gamma 0.9, where the wall never pulls away from the body (a run
# with no impact and a warning), so the gather of empty runs and of warnings is exercised.
# Usage: rig_sweep_mpi.sh HERTZDASH_BIN MPIEXEC
set -euo pipefail
bin=$1
mpiexec=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
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
# Open MPI refuses root without these; --oversubscribe allows 2 ranks on any machine.
# Under `make sanitize`, Open MPI's plugins are dlopen'd and unloaded before LeakSanitizer reports,
# so their leaks show as "<unknown module>", which no suppression (tests/lsan-suppressions.txt)
# can name: leak checking is off for the MPI run only. Our code's leaks are checked by the
# threaded run of the same sweep above, which runs every line the ranks run but the gather.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
  "$mpiexec" -n 2 "$bin" sweep case.toml --out rig-mpi.csv --quiet > /dev/null 2> rig-mpi.err || { cat rig-mpi.err; exit 1; }
grep -q '^# timing: .* on 2 processes x ' rig-mpi.csv || { echo "MPI did not start 2 processes"; exit 1; }
diff <(grep -v '^# timing:' rig-threads.csv) <(grep -v '^# timing:' rig-mpi.csv)
cmp rig-threads.impacts.csv rig-mpi.impacts.csv
# Run 0 (gamma 0.9: its contact does not end within 2 drive cycles) gathered with its warning code
# (the column before `error`).
[ "$(awk -F, '!/^#/ && $1 == "0" { print $(NF - 1) }' rig-mpi.csv)" = rig_warning ] || { echo "the warning of run 0 is missing"; exit 1; }
[ "$(grep -vc '^#' rig-mpi.impacts.csv)" -eq 73 ] || { echo "expected the diagram's 72 impacts in the rig's table"; exit 1; }
echo "mpirun -n 2 and 2 threads wrote the same diagram"
