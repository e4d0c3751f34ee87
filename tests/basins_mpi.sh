#!/usr/bin/env bash
# `hertzdash basins` under `mpirun -n 3` writes the same grid as on 2 threads, byte for byte but for
# the recorded number of processes: process r of 3 runs the rows r, r + 3, ... (16 rows: unequal
# shares) and process 0 numbers the attractors over the whole grid, in the order of their first
# cell (simulation/orbits/basins.hpp). Two grids: the shaker's instantaneous map at e = 0.8,
# Gamma = 0.8, where a period-1 orbit, rest and a period-2 orbit coexist (docs/orbits.md), and its
# soft contacts, where every process runs its own copies of the soft contact.
# Usage: basins_mpi.sh HERTZDASH_BIN MPIEXEC
set -euo pipefail
bin=$1
mpiexec=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
for model in instantaneous soft; do
  args=(basins shaker --impact-model "$model" --restitution 0.8 --gamma 0.8 --resolution 16 --cell-transient 60
        --cell-impacts 8 --section-phase 0.68 --position-min -0.02 --position-max 0.03 --velocity-min -0.5 --velocity-max 0.5)
  "$bin" "${args[@]}" --threads 2 --csv "threads-$model.csv" > /dev/null 2> "threads-$model.err" ||
    { cat "threads-$model.err"; exit 1; }
  # As in tests/rig_sweep_mpi.sh: Open MPI runs as root with these, and LeakSanitizer cannot name the
  # leaks of Open MPI's unloaded plugins (the threaded run above checks ours).
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    "$mpiexec" -n 3 "$bin" "${args[@]}" --csv "mpi-$model.csv" > "mpi-$model.out" 2> "mpi-$model.err" ||
    { cat "mpi-$model.err"; exit 1; }
  grep -q '^# processes: 3$' "mpi-$model.csv" || { echo "$model: MPI did not share the grid among 3 processes"; exit 1; }
  diff <(grep -v '^# processes:' "threads-$model.csv") <(grep -v '^# processes:' "mpi-$model.csv")
  # One report, from process 0.
  [ "$(grep -c '^hertzdash basins shaker' "mpi-$model.out")" -eq 1 ] || { echo "$model: not one report"; exit 1; }
  # More than one attractor, so that their numbering over the processes is exercised.
  [ "$(grep -c '^# attractor 1' "mpi-$model.csv")" -ge 1 ] || { echo "$model: a single attractor"; exit 1; }
done
echo "mpirun -n 3 and 2 threads wrote the same basins"
