#!/usr/bin/env bash
# A process pays only for what its command uses: commands that neither draw nor encode load no
# Mesa, EGL, FreeType, libpng, FFmpeg or Open MPI, and stay under 30 shared objects; a still
# loads the renderer's libraries and a movie FFmpeg (glibc's LD_DEBUG=files lists every object
# the dynamic loader maps, linked or opened with dlopen).
#   usage: lazy_libraries_test.sh HEXGAIT
set -euo pipefail
hexgait=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
heavy='libOSMesa|libEGL|libGL|libfreetype|libpng|libavcodec|libavformat|libavutil|libmpi|libLLVM'

# The objects one command maps, one name per line; a command that fails fails the test.
objects() {
  if ! LD_DEBUG=files "$@" 2>"$work/ld" >/dev/null; then
    echo "FAIL: $* exited non-zero: $(grep -v 'file=\|find library\|search path\|trying file\|^ *[0-9]*:[[:space:]]*$' "$work/ld" | tail -3)" >&2
    failed=1
  fi
  sed -n 's/^ *[0-9]*:[[:space:]]*file=\([^ ]*\) .*/\1/p' "$work/ld" | sort -u
}

light() {  # light COMMAND...: none of the heavy libraries, at most 30 objects
  local list count
  objects "$hexgait" "$@" >"$work/list"
  list=$(cat "$work/list")
  count=$(printf '%s\n' "$list" | grep -c . || true)
  if printf '%s\n' "$list" | grep -Eq "$heavy"; then
    echo "FAIL: hexgait $* loaded: $(printf '%s\n' "$list" | grep -E "$heavy" | tr '\n' ' ')"
    failed=1
  elif [ "$count" -gt 30 ]; then
    echo "FAIL: hexgait $* loaded $count shared objects (limit 30)"
    failed=1
  else
    echo "ok: hexgait $* loaded $count shared objects, none for drawing, movies or MPI"
  fi
}

needs() {  # needs PATTERN COMMAND...: the command loads a library matching PATTERN
  local pattern=$1
  shift
  objects "$hexgait" "$@" >"$work/list"
  if grep -Eq "$pattern" "$work/list"; then
    echo "ok: hexgait $1 loads $pattern"
  else
    echo "FAIL: hexgait $* did not load $pattern"
    failed=1
  fi
}

if readelf -d "$hexgait" | grep NEEDED | grep -Eq "$heavy"; then
  echo "FAIL: hexgait links a drawing, movie or MPI library: $(readelf -d "$hexgait" | grep NEEDED)"
  failed=1
fi
light --help
light simulate --time 1
light inspect
light evolve --population 2 --generations 1 --time 5 --out "$work/run"
light repertoire --evaluations 20 --batch 10 --time 5 --showcase 0 --out "$work/rep"
needs 'libpng16' still --size 64x48 --out "$work/s.png"
needs 'libEGL|libOSMesa' still --size 64x48 --out "$work/s2.png"
needs 'libavcodec' render --time 2 --size 64x48 --out "$work/m.mp4"
exit $failed
