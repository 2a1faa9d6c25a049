#!/usr/bin/env bash
# What a command will load or run is found before its work (run/runtime_needs.h): with libpng,
# FFmpeg or gnuplot unusable, each command ends at once with exit status 4 (a system error, not
# the user's input), a one-line message naming the library or tool and why it failed, and no
# output. The runs asked for are long (a still at t = 900000, a 100,000-evaluation repertoire),
# so a check made after the work would run into ctest's timeout instead of passing. A disk that
# fills up while writing is exit status 4 as well.
#   usage: runtime_needs_test.sh HEXGAIT GENOME
set -euo pipefail
hexgait=$(realpath "$1")
genome=$(realpath "$2")
timeout=$(command -v timeout)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failed=0

# A libpng that is "installed" but damaged: an empty file where the loader looks first.
mkdir broken_png
: >broken_png/libpng16.so.16
# An FFmpeg whose own dependency is missing: a real shared object named as libavcodec, linked
# against a library that exists when it is built and is removed afterwards.
mkdir dep broken_ffmpeg
echo 'int hexgait_test_dep(void) { return 1; }' >dep/dep.c
echo 'int hexgait_test_dep(void); int f(void) { return hexgait_test_dep(); }' >dep/codec.c
cc -shared -fPIC -o dep/libhexgait_test_dep.so.1 -Wl,-soname,libhexgait_test_dep.so.1 dep/dep.c
cc -shared -fPIC -o broken_ffmpeg/libavcodec.so.59 dep/codec.c -Ldep -l:libhexgait_test_dep.so.1
rm dep/libhexgait_test_dep.so.1

# expect NAME OUTPUT MESSAGE ENV... -- ARGS...: exit 4, one line containing MESSAGE, no OUTPUT.
expect() {
  local name=$1 output=$2 message=$3
  shift 3
  local env=()
  while [ "$1" != "--" ]; do env+=("$1"); shift; done
  shift
  local status=0
  env "${env[@]}" "$timeout" 120 "$hexgait" "$@" >"$name.out" 2>"$name.err" || status=$?
  if [ "$status" != 4 ]; then
    echo "FAIL: $name: exit $status, want 4: $(cat "$name.err")"
    failed=1
  elif ! grep -qF -- "$message" "$name.err"; then
    echo "FAIL: $name: the message does not say '$message': $(cat "$name.err")"
    failed=1
  elif [ "$(wc -l <"$name.err")" != 1 ]; then
    echo "FAIL: $name: not one line: $(cat "$name.err")"
    failed=1
  elif [ -e "$output" ]; then
    echo "FAIL: $name: $output was written"
    failed=1
  fi
}

png="libpng16.so.16 (Debian package libpng16-16) is installed but cannot be loaded: $work/broken_png/libpng16.so.16"
expect still s.png "cannot read or write PNG files: $png" LD_LIBRARY_PATH="$work/broken_png" -- \
  still --time 900000 --allow-long --out s.png
expect filmstrip f.png "cannot read or write PNG files: $png" LD_LIBRARY_PATH="$work/broken_png" -- \
  filmstrip --cycle 10000 --allow-long --out f.png
ffmpeg="is installed but cannot be loaded: it needs libhexgait_test_dep.so.1, which is missing"
expect render m.mp4 "$ffmpeg" LD_LIBRARY_PATH="$work/broken_ffmpeg" -- \
  render --time 5 --size 64x48 --out m.mp4
expect movie_set movies "$ffmpeg" LD_LIBRARY_PATH="$work/broken_ffmpeg" -- \
  movie --out movies
gnuplot="gnuplot not found on PATH"
expect repertoire rep "$gnuplot" PATH="$work/nowhere" -- \
  repertoire --evaluations 100000 --allow-long --no-movie --out rep
expect repertoire_movie rep "$ffmpeg" LD_LIBRARY_PATH="$work/broken_ffmpeg" -- \
  repertoire --evaluations 100000 --allow-long --out rep
expect endurance endurance "$gnuplot" PATH="$work/nowhere" -- \
  endurance --genome "$genome" --random 1000 --allow-long --out endurance

# figures and adapt need a run and a repertoire first, made with every tool present.
"$hexgait" evolve --generations 1 --time 50 --quiet --out run
expect figures figs "$gnuplot" PATH="$work/nowhere" -- figures --run run --out figs
expect figures_png figs "cannot read or write PNG files: $png" LD_LIBRARY_PATH="$work/broken_png" -- \
  figures --run run --out figs
"$hexgait" repertoire --evaluations 40 --batch 20 --time 50 --no-movie --compare-ga 0 --quiet \
  --out rep >/dev/null
expect adapt adapt "$gnuplot" PATH="$work/nowhere" -- \
  adapt --repertoire rep --damage left_rear:weak=0.2 --no-movie --out adapt
expect adapt_movie adapt "$ffmpeg" LD_LIBRARY_PATH="$work/broken_ffmpeg" -- \
  adapt --repertoire rep --damage left_rear:weak=0.2 --out adapt

# A disk that fills up while a file is written (a file size limit stands in for it: past it a
# write fails with EFBIG once SIGXFSZ is ignored) is the machine's failure too: exit 4, the file
# named, no file and no temporary file left.
status=0
(trap '' XFSZ; ulimit -f 1; exec "$hexgait" still --size 320x240 --out full.png) \
  >full.out 2>full.err || status=$?
if [ "$status" != 4 ] || ! grep -q "'full.png' failed: File too large" full.err; then
  echo "FAIL: a write past the disk's space: exit $status: $(cat full.err)"
  failed=1
elif compgen -G "full.png*" >/dev/null; then
  echo "FAIL: a write past the disk's space left $(echo full.png*)"
  failed=1
fi

if [ "$failed" = 0 ]; then echo "runtime needs: every command stopped before its work"; fi
exit "$failed"
