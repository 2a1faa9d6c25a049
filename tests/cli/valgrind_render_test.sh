#!/usr/bin/env bash
# Valgrind memcheck on the render path: a still (the GL context, the renderer, libpng), a
# filmstrip (FreeType captions, more frames) and a short movie (the colour conversion, libx264,
# the encoder thread). Any leak or memory error that is not one of Mesa's or glibc's own
# (tests/support/valgrind.supp) fails the test. Skipped (77) when valgrind is not installed.
set -u
hexgait=$(realpath "$1")
supp=$(realpath "$(dirname "$0")/../support/valgrind.supp")
command -v valgrind >/dev/null || { echo "valgrind not installed: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The OSMesa backend, whose Mesa leaks valgrind.supp names; the EGL backend's render path is
# checked by LeakSanitizer in the sanitizer build (GoldenTest.*/egl, gl_backends).
export HEXGAIT_GL=osmesa
status=0
# Valgrind 3.19 cannot emulate every instruction of every CPU: on some AMD EPYC hosts a library
# FFmpeg loads (libhwy, through libjxl) executes rdtscp in its static initialiser, which
# valgrind's virtual CPU refuses with SIGILL. hexgait opens FFmpeg only for a movie, so the
# still and filmstrip run here all the same, and a movie that valgrind stops so is skipped and
# left to LeakSanitizer, which checks every movie test of the sanitizer build (cli_render_run,
# MovieTest.*). The movie run is its own probe: a separate one cost as much as the movie.
# run ARGS...: hexgait ARGS under memcheck. (The subshell waits for valgrind, so a shell's
# "Illegal instruction" line stays quiet.)
run() {
  if (valgrind --quiet --leak-check=full --errors-for-leak-kinds=definite,indirect \
      --error-exitcode=9 --suppressions="$supp" "$hexgait" "$@" >"$work/log" 2>&1; exit $?) 2>/dev/null; then
    echo "clean: hexgait $*"
  elif [ "$1" = render ] && grep -q "signal 4 (SIGILL)" "$work/log"; then
    echo "skipped the movie: valgrind cannot run FFmpeg's libraries on this CPU ($(grep -m1 -o 'Illegal opcode.*' "$work/log" || echo SIGILL)); LeakSanitizer checks it"
  else
    echo "FAIL: valgrind reports errors for: hexgait $*"
    cat "$work/log"
    status=1
  fi
}
run still --size 64x48 --out "$work/still.png"
run filmstrip --frames 2 --size 128x48 --out "$work/strip.png"
run render --time 3 --size 64x48 --fps 10 --speed 10 --out "$work/movie.mp4"
exit $status
