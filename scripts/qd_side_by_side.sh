#!/usr/bin/env bash
# MAP-Elites against MAP-Elites with iso+line variation and CMA-MAE on the same budget
# (docs/results.md, "CMA-MAE against MAP-Elites"):
# `hexgait repertoire` with each algorithm's defaults, seeds 1-3, EVALUATIONS each (10,000
# unless given), the paper's time of 1000 units, the default precision (float, admissions
# confirmed in double). Extra arguments are CMA-MAE settings for a further row ("--learning-rate
# 1" makes a CMA-ME row). Prints one row per run, then the median over seeds per algorithm:
# filled cells, QD-score, the farthest standing gait and the wall time, with the machine's CPU.
# ALGORITHMS (a space-separated list) runs only those.
#   scripts/qd_side_by_side.sh [EVALUATIONS [CMA-MAE FLAGS...]] > table.md
set -euo pipefail
cd "$(dirname "$0")/.."
evaluations=${1:-10000}
shift $(($# > 0 ? 1 : 0))
hexgait=$(realpath "${HEXGAIT:-build/hexgait}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
echo
echo "| algorithm | seed | cells | QD-score | farthest | wall s |"
echo "|---|---|---|---|---|---|"
read -r -a runs <<< "${ALGORITHMS:-map-elites iso-line cma-mae}"
[ $# -eq 0 ] || runs+=("cma-mae $*")
for run in "${runs[@]}"; do
  for seed in 1 2 3; do
    out="$work/$(echo "$run" | tr -c 'a-z0-9' '_')-$seed"
    # shellcheck disable=SC2086 # the run's words are its flags
    "$hexgait" repertoire --algorithm $run --seed "$seed" --evaluations "$evaluations" \
      --no-movie --quiet --out "$out" >/dev/null
    python3 - "$out/repertoire.json" "$run" "$seed" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
m = r["methods"][0]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {m['filled']} | {m['qd_score']:.1f} | "
      f"{m['best_standing']:.3f} | {m['seconds']:.0f} |")
PY
  done
done | tee "$work/rows"
echo
echo "Medians over the seeds:"
echo
echo "| algorithm | cells | QD-score | farthest | wall s |"
echo "|---|---|---|---|---|"
python3 - "$work/rows" <<'PY'
import statistics, sys
rows = {}
for line in open(sys.argv[1]):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    rows.setdefault(cells[0], []).append([float(c) for c in cells[2:]])
for name, values in rows.items():
    med = [statistics.median(column) for column in zip(*values)]
    print(f"| {name} | {med[0]:.0f} | {med[1]:.1f} | {med[2]:.3f} | {med[3]:.0f} |")
PY
