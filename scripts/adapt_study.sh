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
for seed in 1 2 3; do
  rep="$out/repertoire_$seed"
  if [ ! -f "$rep/repertoire.json" ]; then
    "$hexgait" repertoire --evaluations 20000 --seed "$seed" --no-movie --compare-ga 0 --quiet \
      --out "$rep"
  fi
  for leg in right_front right_middle right_rear left_front left_middle left_rear; do
    for kind in weak=0.2 locked short=0.8; do
      damage="$leg:$kind"
      for scale in 0.4 0.2 0.1; do
        dir="$out/adapt_${seed}_${leg}_${kind/=/}_l$scale"
        [ -f "$dir/adapt.json" ] && continue
        if ! "$hexgait" adapt --repertoire "$rep" --damage "$damage" --length-scale "$scale" \
             --normalise none \
             --seed "$seed" --no-movie --out "$dir" >"$out/log_tmp" 2>&1; then
          mkdir -p "$dir"; mv "$out/log_tmp" "$dir/refused.txt"
        fi
      done
    done
  done
done
/usr/bin/python3 scripts/adapt_study.py "$out"
