#!/usr/bin/env bash
# `pip install .` from a clean clone into a fresh venv (Debian's pip, setuptools and pybind11;
# nothing fetched), then `import hexgait` from another folder with no PYTHONPATH gives the
# command line's result; a Python without numpy is told which interpreter the module needs.
# The module is built in BUILD_DIR (the suite's own tree, up to date: seconds) unless
# HEXGAIT_PIP_FULL_BUILD=1, which builds it from the clone alone (minutes: setup.py's default).
#   usage: pip_install_test.sh SOURCE_DIR BUILD_DIR HEXGAIT PYTHON
set -euo pipefail
source_dir=$(realpath "$1")
build_dir=$(realpath "$2")
hexgait=$(realpath "$3")
python=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH

if [ -d "$source_dir/.git" ]; then
  git clone -q "$source_dir" "$work/clone"
else  # a source tree without its history (an archive): copy what git would have
  cp -r "$source_dir" "$work/clone"
  rm -rf "$work/clone"/build*
fi
"$python" -m venv --system-site-packages "$work/env"
if [ "${HEXGAIT_PIP_FULL_BUILD:-0}" = 1 ]; then
  "$work/env/bin/pip" install -q --no-build-isolation --no-index "$work/clone"
else
  HEXGAIT_BUILD_DIR="$build_dir" "$work/env/bin/pip" install -q --no-build-isolation --no-index \
    "$work/clone"
fi

mkdir "$work/elsewhere"
cd "$work/elsewhere"
want=$("$hexgait" simulate --unoptimized --time 100 --json |
  "$python" -c 'import json, sys; print(repr(json.load(sys.stdin)["distance"]))')
"$work/env/bin/python" - "$work/env" "$want" <<'PY'
import sys
import numpy as np
import hexgait
assert hexgait.__file__.startswith(sys.argv[1]), hexgait.__file__
got = hexgait.Evaluator(time=100).evaluate(np.zeros((1, 120), np.int8))["distance"][0]
assert repr(float(got)) == sys.argv[2], (got, sys.argv[2])
print("installed module:", hexgait.__file__, "distance", got)
PY
# The clone is left as it was: the build happens in its ignored build/ folder.
if [ -d "$work/clone/.git" ] && [ -n "$(git -C "$work/clone" status --porcelain)" ]; then
  echo "FAIL: pip install changed the checkout:"; git -C "$work/clone" status --porcelain; exit 1
fi

# A Python without numpy: the import error names the interpreter the module was built for.
"$python" -m venv "$work/bare"
if PYTHONPATH="$work/env/lib/$(ls "$work/env/lib")/site-packages" \
  "$work/bare/bin/python" -c "import hexgait" 2>"$work/err"; then
  echo "FAIL: imported without numpy"; exit 1
fi
grep -q "hexgait needs numpy, which .* cannot import: run the Python it was built for" "$work/err" ||
  { echo "FAIL: not the numpy message:"; cat "$work/err"; exit 1; }
echo "pip install: passed"
