#!/usr/bin/env bash
# The installed package, used as a user would: install the build tree into a scratch
# prefix, build tests/install_consumer/ against it with find_package(hertzdash), run it,
# run the installed program, and import the installed Python module. Nothing of the build
# or source tree is on any path the consumer sees.
# Usage: install_consumer.sh BUILD_DIR SOURCE_DIR PYTHON CMAKE [with-python-module|without-python-module]
# (the interpreter the module is built for, the cmake that built the tree; whether the tree has
# the Python module, HERTZDASH_WITH_PYTHON)
# Under make sanitize, HERTZDASH_PYTHON_PRELOAD is the sanitizer runtime the Python that imports
# the instrumented module needs (tests/CMakeLists.txt); no other tool of this script gets it.
set -euo pipefail
build=$(realpath "$1"); src=$(realpath "$2"); python=$3; cmake=$4; module=${5:-with-python-module}
python_with_module() { LD_PRELOAD="${HERTZDASH_PYTHON_PRELOAD-}" "$python" "$@"; }
work="$build/install-test"
rm -rf "$work"
prefix="$work/prefix"
"$cmake" --install "$build" --prefix "$prefix" > "$work.log"
unset HERTZDASH_DATA_DIR PYTHONPATH
# Installed files find each other relative to themselves, never through the build tree.
installed=("$prefix"/bin/hertzdash "$prefix"/lib/libhertzdash_*.so)
[ "$module" = without-python-module ] || installed+=("$prefix"/lib/python3/dist-packages/hertzdash.*.so)
for f in "${installed[@]}"; do
  runpath=$(readelf -d "$f" | sed -n 's/.*R\(UN\)\?PATH.*\[\(.*\)\]/\2/p')
  case "$runpath" in
    *"$build"*|*"$src"*) echo "FAILED: $f has run path $runpath into the build or source tree" >&2; exit 1 ;;
    '$ORIGIN'*) ;;
    *) echo "FAILED: $f has run path '$runpath', not relative to \$ORIGIN" >&2; exit 1 ;;
  esac
done
# The README's project: its ```cmake and ```cpp blocks after the line that names this script,
# built exactly as written (no C++ standard set: the package must bring it).
readme_block() {
  awk -v lang="$1" '/tests\/install_consumer.sh/ {found = 1; next} found && $0 == "```" lang {inside = 1; next}
       inside && /^```$/ {exit} inside {print}' "$src/README.md"
}
mkdir -p "$work/readme_project"
readme_block cmake > "$work/readme_project/CMakeLists.txt"
readme_block cpp > "$work/readme_project/my_program.cpp"
for f in CMakeLists.txt my_program.cpp; do
  [ -s "$work/readme_project/$f" ] || { echo "FAILED: no $f for the README's project found in README.md" >&2; exit 1; }
done
# The package needs no nlohmann_json of its users (cmake/hertzdashConfig.cmake.in): the projects are
# configured as if it were not installed.
for project in "$work/readme_project" "$src/tests/install_consumer"; do
  "$cmake" -S "$project" -B "$work/build-$(basename "$project")" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=TRUE > /dev/null
  "$cmake" --build "$work/build-$(basename "$project")" > /dev/null
done
"$work/build-install_consumer/consumer"
# The README example prints the values `hertzdash simulate` reports for the same run.
expected=$("$build/hertzdash" simulate --integrator gbs8-regularized --json |
  "$python" -c 'import json, sys; j = json.load(sys.stdin)
print("e_effective %.6f, peak force %.1f N" % (j["e_effective"], j["peak_force_N"]))')
got=$("$work/build-readme_project/my_program")
[ "$got" = "$expected" ] || { echo "FAILED: README example printed '$got', expected '$expected'" >&2; exit 1; }
echo "README C++ example: $got"
"$prefix/bin/hertzdash" --version
"$prefix/bin/hertzdash" simulate --rod steel --height 0.02 --json > "$work/cli.json"
if [ "$module" = without-python-module ]; then
  echo "installed python module: not built (HERTZDASH_WITH_PYTHON), not checked"
else
  pydir=$(find "$prefix" -name 'hertzdash.cpython-*.so' -printf '%h\n')
  PYTHONPATH="$pydir" python_with_module - "$work/cli.json" <<'PY'
import json, sys
import hertzdash
cli = json.load(open(sys.argv[1]))
py = hertzdash.simulate(rod="steel", height=0.02)
assert py["e_effective"] == cli["e_effective"], (py["e_effective"], cli["e_effective"])
print("installed python module:", hertzdash.__file__, "e_effective", py["e_effective"])
PY
fi

# Without the tables beside it the installed program says where it looked and how to
# point at them; HERTZDASH_DATA_DIR overrides the search.
mv "$prefix/share/hertzdash/data" "$work/data-moved"
if "$prefix/bin/hertzdash" simulate > "$work/no-data.out" 2> "$work/no-data.err"; then
  echo "FAILED: the installed program ran without its data tables" >&2; exit 1
fi
grep -q "HERTZDASH_DATA_DIR" "$work/no-data.err" && grep -q "share/hertzdash/data" "$work/no-data.err" \
  || { echo "FAILED: unhelpful message without the data tables:" >&2; cat "$work/no-data.err" >&2; exit 1; }
[ ! -s "$work/no-data.out" ] || { echo "FAILED: output without the data tables" >&2; exit 1; }
HERTZDASH_DATA_DIR="$work/data-moved" "$prefix/bin/hertzdash" simulate --json > /dev/null
echo "install_consumer: all checks passed"
