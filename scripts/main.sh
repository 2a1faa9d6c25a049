#!/usr/bin/env bash
# The main job: build, then reproduce the paper's experiment (evolve with the paper's
# settings, seed 1) and compare the unoptimised and evolved programs.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
scripts/build.sh
build/hexgait evolve --seed 1 --out out/run
echo
echo "== the evolved program, re-run on its own:"
build/hexgait simulate --genome out/run/best.genome
echo
build/hexgait still --out out/figure1.png
build/hexgait render --unoptimized --out out/unoptimized.mp4
build/hexgait render --genome out/run/best.genome --out out/evolved.mp4
# Until 'hexgait movie' writes the side-by-side comparison, the report shows the evolved movie
# in its place.
[ -f out/comparison.mp4 ] || cp out/evolved.mp4 out/comparison.mp4
echo
echo "== figures ($((SECONDS - start)) s so far)"
build/hexgait figures --run out/run
echo
echo "== report page ($((SECONDS - start)) s so far)"
build/hexgait report --run out/run
echo
echo "done in $((SECONDS - start)) s; results in out/run/ (fitness.csv, best.genome, run.json),"
echo "out/figure1.png (the paper's Figure 1), out/unoptimized.mp4 and out/evolved.mp4,"
echo "out/figures/ (every figure as PNG, SVG, CSV and gnuplot script)"
echo "report: out/report/index.html (self-contained: open it from disk or attach the folder)"
