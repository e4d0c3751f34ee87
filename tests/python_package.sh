#!/usr/bin/env bash
# The Python module the Python way (issue 32): a venv of PYTHON with its system site packages
# (Debian's NumPy), `pip install --no-build-isolation` of the source tree into it, offline, and the
# installed module checked from outside both trees (tests/python_package_check.py).
# setup.py links the module in BUILD_DIR from the objects the build compiled (HERTZDASH_CMAKE_BUILD_DIR,
# target hertzdash_python_wheel): the same one-file module with no run path that a pip install
# without a build tree compiles from scratch, in seconds instead of minutes. What setuptools writes
# is under BUILD_DIR/python-package-test (HERTZDASH_PYTHON_BUILD_DIR); the source tree is left as it was.
# Usage: python_package.sh BUILD_DIR SOURCE_DIR PYTHON HERTZDASH
#   (the interpreter CMake found, Python_EXECUTABLE; the build tree's program, for the reference run)
set -euo pipefail
usage="usage: python_package.sh BUILD_DIR SOURCE_DIR PYTHON HERTZDASH"
build=$(realpath "${1:?$usage}"); src=$(realpath "${2:?$usage}"); python=${3:?$usage}; hertzdash=${4:?$usage}
work="$build/python-package-test"
rm -rf "$work"
mkdir -p "$work"
unset PYTHONPATH HERTZDASH_DATA_DIR PIP_REQUIRE_VIRTUALENV

# The files and directories of the source tree git does not track (ignored or not: build/ is one),
# and what setuptools would leave in it; edits of tracked files are not pip's.
tree_state() {
  if git -C "$src" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    git -C "$src" status --porcelain --ignored | grep '^\(??\|!!\)' || true
  fi
  find "$src" -maxdepth 1 \( -name '*.egg-info' -o -name build-python \) -print
}
tree_state > "$work/tree-before"

"$python" -m venv --system-site-packages "$work/venv"
start=$(date +%s)
if ! (cd "$work" && HERTZDASH_PYTHON_BUILD_DIR="$work/pip-build" HERTZDASH_CMAKE_BUILD_DIR="$build" \
      PIP_DISABLE_PIP_VERSION_CHECK=1 \
      "$work/venv/bin/python" -m pip install --no-build-isolation --no-index --no-cache-dir "$src") \
    > "$work/pip.log" 2>&1; then
  tail -n 40 "$work/pip.log" >&2
  echo "FAILED: pip install --no-build-isolation $src (log: $work/pip.log)" >&2; exit 1
fi
echo "pip install: $(( $(date +%s) - start )) s"

tree_state > "$work/tree-after"
if ! diff "$work/tree-before" "$work/tree-after" >&2; then
  echo "FAILED: pip install changed the source tree $src (above)" >&2; exit 1
fi
# One file, with no run path: nothing of the build tree is needed, and no library is looked for
# in the current directory (an empty run path entry).
module=$(find "$work/venv" -name 'hertzdash.cpython-*.so')
[ "$(echo "$module" | wc -l)" = 1 ] && [ -n "$module" ] || { echo "FAILED: no single module in the venv: '$module'" >&2; exit 1; }
if readelf -d "$module" | grep -q 'R\(UN\)\?PATH'; then
  echo "FAILED: $module has a run path: $(readelf -d "$module" | grep 'R\(UN\)\?PATH')" >&2; exit 1
fi

"$hertzdash" simulate --rod steel --height 0.02 --json > "$work/program.json" 2> "$work/program.err"
# Isolated (-I: no PYTHON* variables, not the script's directory on sys.path), from the test's
# directory: neither tree can supply the module.
(cd "$work" && "$work/venv/bin/python" -I -B "$src/tests/python_package_check.py" "$work/program.json")
echo "python_package: all checks passed"
