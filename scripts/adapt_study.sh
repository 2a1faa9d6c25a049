#!/usr/bin/env bash
# Adapting to damage, measured: repertoires of 20,000 evaluations for seeds 1-3, then
# `hexgait adapt` on every leg x three kinds of damage (weak=0.2, locked, short=0.8) for each,
# with the paper's length scale (0.4) and two shorter ones (0.2, 0.1), distances as they are (the
# paper's code; scripts/adapt_gp_study.py varies the rest). scripts/adapt_study.py turns the
# adapt.json files into the table of docs/results.md ("Adapting to damage").
#   scripts/adapt_study.sh [OUT_DIR]     (default out/adapt_study; about 20 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/adapt_study}
hexgait=build/hexgait
[ -x "$hexgait" ] || { echo "build first: cmake --build build" >&2; exit 1; }
mkdir -p "$out"
source scripts/adapt_common.sh
for seed in 1 2 3; do
  rep="$out/repertoire_$seed"
  ensure_map "$hexgait" "$rep" 20000 "$seed"
  for scale in 0.4 0.2 0.1; do
    adapt_each_leg "$hexgait" "$rep" "$out/adapt_$seed" "_l$scale" "weak=0.2 locked short=0.8" \
      "$seed" --length-scale "$scale" --normalise none
  done
done
/usr/bin/python3 scripts/adapt_study.py "$out"
