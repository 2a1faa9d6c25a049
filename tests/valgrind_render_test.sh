#!/usr/bin/env bash
# Valgrind memcheck on the render path: a still (OSMesa, libpng) and a short movie (FreeType
# captions, the colour conversion, libx264, the encoder thread). Any leak or memory error that is not one of
# Mesa's own (tests/valgrind.supp) fails the test. Skipped (77) when valgrind is not installed.
set -u
hexgait=$(realpath "$1")
supp=$(realpath "$(dirname "$0")/valgrind.supp")
command -v valgrind >/dev/null || { echo "valgrind not installed: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The OSMesa backend, whose Mesa leaks valgrind.supp names; the EGL backend's render path is
# checked by LeakSanitizer in the sanitizer build (GoldenTest.*/egl, gl_backends).
export HEXGAIT_GL=osmesa
# Valgrind 3.19 cannot emulate every instruction of every CPU: on some AMD EPYC hosts the
# static initialiser of a system library (libhwy, loaded by the video libraries) executes
# rdtscp, which valgrind's virtual CPU refuses with SIGILL before main() starts. That says
# nothing about hexgait's memory, so the test is skipped there, naming why.
if ! valgrind --quiet "$hexgait" --version >"$work/preflight" 2>&1; then
  if grep -q "signal 4 (SIGILL)" "$work/preflight"; then
    echo "valgrind cannot run the binary's libraries on this CPU: skipped"
    grep -m1 "Illegal opcode" -A1 "$work/preflight"
    exit 77
  fi
fi
status=0
run() {
  if ! valgrind --quiet --leak-check=full --errors-for-leak-kinds=definite,indirect \
      --error-exitcode=9 --suppressions="$supp" "$hexgait" "$@" >"$work/log" 2>&1; then
    echo "FAIL: valgrind reports errors for: hexgait $*"
    cat "$work/log"
    status=1
  else
    echo "clean: hexgait $*"
  fi
}
run still --size 64x48 --out "$work/still.png"
run render --time 3 --size 64x48 --fps 10 --speed 10 --out "$work/movie.mp4"
exit $status
