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
echo
echo "== movies of both programs, and both on one clock:"
build/hexgait movie --run out/run --out out
echo
echo "done in $((SECONDS - start)) s; results in out/run/ (fitness.csv, best.genome, run.json),"
echo "out/figure1.png (the paper's Figure 1), out/unoptimized.mp4, out/evolved.mp4 and"
echo "out/comparison.mp4"
