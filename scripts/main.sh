#!/usr/bin/env bash
# The main job: build what it needs (hexgait alone: no tests, benchmarks or Python module),
# reproduce the paper's experiment (evolve with the paper's settings, seed 1), then make
# everything a report needs: Figure 1, the gait movies, the figures, a small repertoire of gaits
# (MAP-Elites; REPERTOIRE_EVALUATIONS, default 5000: see docs/results.md for why that many, and
# scripts/repertoire.sh for the 100,000-evaluation run) and one report page. Prints a progress
# line per stage and where the report is.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
stage() { echo; echo "== [$1/11] $2 ($((SECONDS - start)) s so far)"; }
stage 1 "build"
scripts/build.sh --main
stage 2 "evolve with the paper's settings (population 4, 10 generations, seed 1)"
build/hexgait evolve --seed 1 --out out/run
stage 3 "the evolved program, re-run on its own"
build/hexgait simulate --genome out/run/best.genome
stage 4 "the paper's Figure 1"
build/hexgait still --out out/figure1.png
stage 5 "filmstrip: one gait cycle of the evolved program"
build/hexgait filmstrip --genome out/run/best.genome --out out/filmstrip.png
stage 6 "movies: unoptimized, evolved, and both on one clock (footprints, swinging legs, footfall strip)"
build/hexgait movie --run out/run --out out --cues footprints,swing,strip
stage 7 "integrator accuracy and stability, short versions (full: hexgait bench accuracy)"
build/hexgait bench accuracy --quick --out out/bench
build/hexgait bench stability --quick --out out/bench
stage 8 "figures"
build/hexgait figures --run out/run --bench out/bench
stage 9 "a repertoire of gaits: MAP-Elites, ${REPERTOIRE_EVALUATIONS:-5000} evaluations"
build/hexgait repertoire --evaluations "${REPERTOIRE_EVALUATIONS:-5000}" --out out/repertoire
stage 10 "adapting to a damaged leg: the right front leg's motor springs at a fifth of their strength"
build/hexgait adapt --repertoire out/repertoire --damage right_front:weak=0.2 --out out/adapt
stage 11 "report page"
build/hexgait report --run out/run --repertoire out/repertoire --adapt out/adapt
echo
echo "done in $((SECONDS - start)) s:"
echo "  out/run/          fitness.csv, best.genome, run.json, checkpoint.json"
echo "  out/figure1.png   the paper's Figure 1"
echo "  out/filmstrip.png one gait cycle of the evolved program, six frames"
echo "  out/*.mp4         unoptimized.mp4, evolved.mp4, comparison.mp4"
echo "  out/*.html        unoptimized.html, evolved.html: the same runs to replay in a browser"
echo "  out/bench/        accuracy.csv, stability.csv, energy_drift.csv (short versions)"
echo "  out/figures/      every figure as PNG, SVG, CSV and gnuplot script"
echo "  out/repertoire/   archive.json/.csv, map.png, progress.png, grid.mp4, elites/*.genome"
echo "  out/adapt/        trials.csv, adapt.png, adapt.mp4: the repertoire adapting to a damaged leg"
echo "report: out/report/index.html (self-contained: open it from disk or attach the folder)"
