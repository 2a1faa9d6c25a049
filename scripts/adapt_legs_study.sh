#!/usr/bin/env bash
# Adapting to damage as Cully et al. studied it (Nature 521, 2015, Extended Data Fig. 4): every
# leg with each damage (weak=0.2, locked, short=0.8, lost), on three maps of each of two methods
# (MAP-Elites and CMA-ME, 20,000 evaluations each, seeds 1-3), with `hexgait adapt`'s defaults
# run for a fixed 17 trials (--no-stop); adapt.json says where the stop rule would have stopped
# and what adaptation and its comparisons had there, so one run gives both cuts. The comparisons:
# the intact best gait, as many random elites, the paper's GA started from the intact best, and
# the best elite found by running them all. scripts/adapt_legs_study.py prints the tables of
# docs/results.md ("Every leg, four damages").
#   scripts/adapt_legs_study.sh [OUT_DIR]   (default out/adapt_legs; a finished run is kept, so
#                                            an interrupted study resumes; ~40 minutes on 2 cores)
# METHODS (default "map-elites cma-me"; cma-mae also), SEEDS (default "1 2 3") and EVALUATIONS
# (default 20000) choose the maps; a map already in OUT_DIR/METHOD_SEED (a folder or a link to
# one) is used as it is.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/adapt_legs}
hexgait=build/hexgait
[ -x "$hexgait" ] || { echo "build first: cmake --build build" >&2; exit 1; }
read -r -a methods <<< "${METHODS:-map-elites cma-me}"
read -r -a seeds <<< "${SEEDS:-1 2 3}"
method_flags() {  # sets flags: the `hexgait repertoire` flags that make METHOD's maps
  case $1 in
    map-elites) flags=(--algorithm map-elites) ;;
    cma-me) flags=(--algorithm cma-mae --learning-rate 1) ;;
    cma-mae) flags=(--algorithm cma-mae) ;;
    *) echo "unknown method '$1' (map-elites, cma-me or cma-mae)" >&2; exit 1 ;;
  esac
}
for method in "${methods[@]}"; do method_flags "$method"; done  # a wrong name before any work
mkdir -p "$out"
source scripts/adapt_common.sh
for method in "${methods[@]}"; do
  method_flags "$method"
  for seed in "${seeds[@]}"; do
    map="$out/${method}_$seed"
    ensure_map "$hexgait" "$map" "${EVALUATIONS:-20000}" "$seed" "${flags[@]}"
    adapt_each_leg "$hexgait" "$map" "$out/adapt_${method}_$seed" "" \
      "weak=0.2 locked short=0.8 lost" "$seed" --trials 17 --no-stop
  done
done
/usr/bin/python3 scripts/adapt_legs_study.py "$out"
