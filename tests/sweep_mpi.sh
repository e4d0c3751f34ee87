#!/usr/bin/env bash
# `mpirun -n 2 hertzdash sweep CASE` writes the same CSV and summary as the threaded run, byte
# for byte apart from the timing line (docs/sweep.md). The case mixes laws (unequal costs), a
# Sobol sample and a failing point, so the round-robin split and the gather of errors are both
# exercised.
# Usage: sweep_mpi.sh HERTZDASH_BIN MPIEXEC
set -euo pipefail
bin=$1
mpiexec=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat > "$dir/case.toml" <<'CASE'
[grid]
damping = ["hongo", "hunt-crossley", "kuwabara-kono"]
ball-radius = [0.0127, 1e-6]
[sample]
method = "sobol"
count = 33
ball-E = { distribution = "uniform", min = 1.2e9, max = 2.9e9 }
height = { distribution = "lognormal", log_mean = -3.9, log_sd = 0.3 }
[output]
columns = ["e_effective", "peak_force_N", "contact_time_s", "steps"]
summary = true
CASE
cd "$dir"
"$bin" sweep case.toml --out threads.csv --summary threads.summary.csv --quiet --threads 2 > threads.out 2> threads.err || true
# Open MPI refuses root without these; --oversubscribe allows 2 ranks on any machine.
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
  "$mpiexec" -n 2 "$bin" sweep case.toml --out mpi.csv --summary mpi.summary.csv --quiet > mpi.out 2> mpi.err || true
for f in threads mpi; do
  [ -s $f.csv ] || { echo "no $f.csv"; cat $f.err; exit 1; }
done
# The timing lines differ (processes x threads) and say so; nothing else may.
grep -q '^# timing: .* on 1 process x 2 threads' threads.csv || { echo "threaded timing line missing"; exit 1; }
grep -q '^# timing: .* on 2 processes x ' mpi.csv || { echo "MPI timing line missing (did MPI start?)"; cat mpi.err; exit 1; }
diff <(grep -v '^# timing:' threads.csv) <(grep -v '^# timing:' mpi.csv)
cmp threads.summary.csv mpi.summary.csv
# Both ran all 198 runs, 99 of them failing (a 1 um ball: its Hertz deformation passes its
# radius), and said so.
rows=$(grep -vc '^#' mpi.csv)
[ "$rows" -eq 199 ] || { echo "expected 198 rows and the column names, got $rows lines"; exit 1; }
grep -q '99 of 198 runs failed' mpi.err || { echo "MPI run did not report the failures"; cat mpi.err; exit 1; }
echo "mpirun -n 2 and 2 threads wrote the same table and summary"
