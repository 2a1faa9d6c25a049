#!/usr/bin/env bash
# How the unoptimised program's fall depends on a built-in creature's constants: each main
# constant moved by -10%, -5%, +5% and +10% on its own, plus ablations. Prints a Markdown table;
# quoted in docs/model.md ("How the constants were chosen").
#   [EVOLVE=1] scripts/sensitivity.sh [hexapod|wedge]     (default: hexapod)
# EVOLVE=1 adds a column: the best gait of `hexgait evolve --seed 1` (the paper's budget) for
# the variant, its ratio to the unoptimised distance, and whether it falls.
set -euo pipefail
cd "$(dirname "$0")/.."
creature=${1:-hexapod}
hexgait=build/hexgait
[ -x "$hexgait" ] || scripts/build.sh
case "$creature" in
  hexapod) prefix="" motor=metachronal.json
           names=(gravity LEG_K LEG_DAMPING friction TRANSITION LIFT STRIDE BELLY_Z FOOT_Y FLANK_MASS) ;;
  wedge) prefix="wedge." motor=wedge_metachronal.json
         names=(gravity LEG_K LEG_DAMPING friction TRANSITION LIFT RIDGE_Z FOOT_Y) ;;
  *) echo "sensitivity.sh: unknown creature '$creature' (hexapod, wedge)" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# run NAME [--set K=V ...]: one row
run() {
  local name=$1
  shift
  mkdir -p "$work/v"
  python3 scripts/make_assets.py --out "$work/v" "$@"
  local row
  row=$("$hexgait" simulate --creature "$work/v/$creature.json" --motor "$work/v/$motor" --json |
    python3 -c "import json,sys; d=json.load(sys.stdin); c=d['fall_cycle']; print(f'| $name | {d[\"distance\"]:.2f} | {d[\"mean_feet_on_ground\"]:.1f} | ' + (f'cycle {c} (t = {d[\"fall_time\"]:.0f})' if d['fell'] else 'no fall') + ' |')")
  if [ "${EVOLVE:-0}" = 1 ]; then
    rm -rf "$work/run"
    "$hexgait" evolve --seed 1 --creature "$work/v/$creature.json" --motor "$work/v/$motor" \
      --out "$work/run" --quiet
    row+=$(python3 -c "import json; r=json.load(open('$work/run/run.json')); b=r['best']; q=r['ratio_best_to_unoptimized']; print(f' {b[\"distance\"]:.2f} (' + (f'{q:.1f}x' if q else '-') + '), ' + ('falls' if b['fell'] else 'no fall') + ' |')")
  fi
  echo "$row"
}
value() {
  python3 -c "import sys; sys.path.insert(0, 'scripts'); import make_assets as m; c = m.WEDGE if '$creature' == 'wedge' else m.HEXAPOD; print(c['PHYSICS'].get('$1', c.get('$1')))"
}
if [ "${EVOLVE:-0}" = 1 ]; then
  echo "| variant | distance | feet down (mean, before a fall) | fall | evolved, seed 1 |"
  echo "|---|---|---|---|---|"
else
  echo "| variant | distance | feet down (mean, before a fall) | fall |"
  echo "|---|---|---|---|"
fi
run "default"
for name in "${names[@]}"; do
  base=$(value "$name")
  for f in 0.9 0.95 1.05 1.1; do
    v=$(python3 -c "print(round($base * $f, 6))")
    run "$name x $f ($v)" --set "$prefix$name=$v"
  done
done
run "rest lengths jump (TRANSITION=0)" --set "${prefix}TRANSITION=0"
if [ "$creature" = wedge ]; then
  first=(--set wedge.LEG_K=40 --set wedge.LEG_DAMPING=2 --set wedge.FOOT_Y=1.1
         --set wedge.MIDDLE_FOOT_Y=1.3 --set wedge.RIDGE_Z=1.25 --set wedge.FLANK_Z=1.0
         --set wedge.TRANSITION=2)
  run "first, quasi-static constants" "${first[@]}"
  run "first constants, rest lengths jump" "${first[@]}" --set wedge.TRANSITION=0
fi
