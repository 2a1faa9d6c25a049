#!/usr/bin/env bash
# The same seed gives bit-identical outputs on every run and with any number of threads; the
# same inputs give byte-identical movies.
set -eu
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(evolve --seed 5 --generations 3 --time 150 --quiet)
"$hexgait" "${args[@]}" --threads 1 --out "$work/t1"
"$hexgait" "${args[@]}" --threads 2 --out "$work/t2"
"$hexgait" "${args[@]}" --threads 2 --out "$work/t2b"
"$hexgait" "${args[@]}" --threads 7 --out "$work/t7"
for run in t2 t2b t7; do
  cmp "$work/t1/fitness.csv" "$work/$run/fitness.csv"
  cmp "$work/t1/best.genome" "$work/$run/best.genome"
done
# And simulate's result is a pure function of its inputs.
a=$("$hexgait" simulate --genome "$work/t1/best.genome" --time 150 --json | grep -v wall_seconds)
b=$("$hexgait" simulate --genome "$work/t1/best.genome" --time 150 --json | grep -v wall_seconds)
[ "$a" = "$b" ]
# A movie is the same file, byte for byte, whatever llvmpipe's thread count (x264's is fixed).
movie=(render --genome "$work/t1/best.genome" --time 60 --size 320x240)
LP_NUM_THREADS=1 "$hexgait" "${movie[@]}" --out "$work/m1.mp4" >/dev/null
LP_NUM_THREADS=3 "$hexgait" "${movie[@]}" --out "$work/m3.mp4" >/dev/null
cmp "$work/m1.mp4" "$work/m3.mp4"
echo "1 passed, 0 failed"
