#!/usr/bin/env bash
# How the unoptimised program's fall depends on the creature's constants: each main constant
# moved by -10%, -5%, +5% and +10% on its own, plus two ablations (rest lengths that jump, and
# the original quasi-static constants). Prints a Markdown table; quoted in docs/model.md.
#   scripts/sensitivity.sh
set -euo pipefail
cd "$(dirname "$0")/.."
hexgait=build/hexgait
[ -x "$hexgait" ] || scripts/build.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# run NAME [--set K=V ...]: one row
run() {
  local name=$1
  shift
  mkdir -p "$work/v"
  python3 scripts/make_assets.py --out "$work/v" "$@"
  "$hexgait" simulate --creature "$work/v/hexapod.json" --motor "$work/v/metachronal.json" --json |
    python3 -c "import json,sys; d=json.load(sys.stdin); c=d['fall_cycle']; print(f'| $name | {d[\"distance\"]:.2f} | {d[\"mean_feet_on_ground\"]:.1f} | ' + (f'cycle {c} (t = {d[\"fall_time\"]:.0f})' if d['fell'] else 'no fall') + ' |')"
}
value() { python3 -c "import sys; sys.path.insert(0, 'scripts'); import make_assets as m; print(m.PHYSICS.get('$1', getattr(m, '$1', None)))"; }
echo "| variant | distance | feet down (mean, before a fall) | fall |"
echo "|---|---|---|---|"
run "default"
for name in gravity LEG_K LEG_ALPHA friction TRANSITION LIFT BODY_TOP FOOT_Y; do
  base=$(value "$name")
  for f in 0.9 0.95 1.05 1.1; do
    v=$(python3 -c "print(round($base * $f, 6))")
    run "$name x $f ($v)" --set "$name=$v"
  done
done
run "rest lengths jump (TRANSITION=0)" --set TRANSITION=0
first=(--set LEG_K=40 --set LEG_ALPHA=0.05 --set FOOT_Y=1.1 --set MIDDLE_FOOT_Y=1.3
       --set BODY_TOP=1.25 --set FLANK_Z=1.0 --set TRANSITION=2)
run "first, quasi-static constants" "${first[@]}"
run "first constants, rest lengths jump" "${first[@]}" --set TRANSITION=0
