#!/usr/bin/env bash
# Both GL backends from the command line: `--gl egl` and `--gl osmesa` (and HEXGAIT_GL) render
# a still and a movie, `--version` names the backend in use, and the two backends' stills are
# the same image (both are Mesa's llvmpipe here; on a GPU they may differ within the goldens'
# tolerance, which tests/unit/golden_test.cc checks on every backend).
set -u
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
for backend in egl osmesa; do
  "$hexgait" still --gl "$backend" --time 3 --size 320x180 --out "$work/$backend.png" >/dev/null ||
    fail "still --gl $backend"
  "$hexgait" render --gl "$backend" --time 2 --size 160x120 --out "$work/$backend.mp4" >/dev/null ||
    fail "render --gl $backend"
  [ -s "$work/$backend.mp4" ] || fail "render --gl $backend wrote no movie"
  HEXGAIT_GL=$backend "$hexgait" --version | grep -q "^OpenGL: $backend: " ||
    fail "HEXGAIT_GL=$backend: --version does not name it"
  # --gl wins over HEXGAIT_GL.
  HEXGAIT_GL=nonsense "$hexgait" still --gl "$backend" --size 160x120 --out "$work/x.png" >/dev/null ||
    fail "--gl $backend did not override HEXGAIT_GL"
done
cmp -s "$work/egl.png" "$work/osmesa.png" || fail "egl and osmesa stills differ"
cmp -s "$work/egl.mp4" "$work/osmesa.mp4" || fail "egl and osmesa movies differ"
echo "$failures failures"
[ $failures -eq 0 ]
