#!/bin/sh
# Arrows point down only (docs/layout.md): every `#include "hertzdash/<folder>/..."` in the
# libraries' sources names a folder of a lower rank than the including file's own folder, or
# that folder itself. Folders of equal rank are peers and never include each other.
#
#   rank 0  ode/  io/
#   rank 1  model/  integrators/
#   rank 2  simulation/run/  simulation/uncertainty/
#   rank 3  simulation/paper/  simulation/shaker/  simulation/export/
#   rank 4  simulation/options/  simulation/orbits/
#   rank 5  simulation/rigs/
#   rank 6  simulation/fit/  simulation/sweep/
#   rank 7  simulation/reports/
# Applications (cli/, python/, validation/, bench/) may include any library folder, and no
# library folder includes an application (that would not compile: they are not under
# include/hertzdash/).
# Usage: include_layers.sh SOURCE_DIR. Prints each offending line; exit 1 if there is one.
set -u
cd "$1" || exit 2
rank() {
  case "$1" in
    ode|io) echo 0 ;;
    model|integrators) echo 1 ;;
    simulation/run|simulation/uncertainty) echo 2 ;;
    simulation/paper|simulation/shaker|simulation/export) echo 3 ;;
    simulation/options|simulation/orbits) echo 4 ;;
    simulation/rigs) echo 5 ;;
    simulation/fit|simulation/sweep) echo 6 ;;
    simulation/reports) echo 7 ;;
    *) echo unknown ;;
  esac
}
# The folder a path belongs to: simulation/<part>, or the top-level folder.
folder_of() {
  case "$1" in
    simulation/*) echo "$1" | cut -d/ -f1-2 ;;
    *) echo "$1" | cut -d/ -f1 ;;
  esac
}
status=0
checked=0
for file in $(find ode io model integrators simulation -name '*.hpp' -o -name '*.cpp' | sort); do
  own=$(folder_of "$file")
  own_rank=$(rank "$own")
  if [ "$own_rank" = unknown ]; then
    echo "$file: folder $own has no rank in tests/include_layers.sh"; status=1; continue
  fi
  for included in $(sed -n 's|^#include "hertzdash/\([^"]*\)".*|\1|p' "$file"); do
    checked=$((checked + 1))
    case "$included" in registered_law_list.hpp) continue ;; esac
    target=$(folder_of "$included")
    [ "$target" = "$own" ] && continue
    target_rank=$(rank "$target")
    if [ "$target_rank" = unknown ] || [ "$target_rank" -ge "$own_rank" ]; then
      echo "$file includes hertzdash/$included: $target (rank $target_rank) is not below $own (rank $own_rank)"
      status=1
    fi
  done
done
# A check that looked at nothing cannot fail: require the includes to have been found.
if [ "$checked" -lt 100 ]; then echo "only $checked includes found: is $1 the source tree?"; exit 1; fi
echo "$checked includes checked"
exit $status
