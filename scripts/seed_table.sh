#!/usr/bin/env bash
# Runs `hexgait evolve` for seeds 1..N with the paper's budget (population 4, 10 generations)
# and a larger one (population 16, 20 generations: 316 evaluations, 9x the paper's), and prints the Markdown table quoted in
# docs/results.md ("Seeds 1-20"). Runs take a while with the larger budget (about 10 minutes on
# 2 cores); progress goes to stderr. CREATURE picks a built-in creature (default: hexapod).
#   [CREATURE=wedge] scripts/seed_table.sh [N=20] [OUT=out/seeds]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-20}
out=${2:-out/seeds}
hexgait=${HEXGAIT:-build/hexgait}
creature=${CREATURE:-hexapod}
[ -x "$hexgait" ] || scripts/build.sh
mkdir -p "$out"
budgets=("4 10" "16 20")
for budget in "${budgets[@]}"; do
  set -- $budget
  for seed in $(seq 1 "$n"); do
    dir="$out/p$1-g$2/seed$seed"
    if [ ! -f "$dir/run.json" ]; then
      echo "seed_table: population $1, $2 generations, seed $seed" >&2
      "$hexgait" evolve --seed "$seed" --population "$1" --generations "$2" --creature "$creature" \
        --out "$dir" --quiet
    fi
  done
done
python3 - "$out" "$n" "$creature" <<'PY'
import json, statistics, sys
out, n, creature = sys.argv[1], int(sys.argv[2]), sys.argv[3]
print("| budget | seeds | evaluations per run | unoptimized distance (fall cycle) | "
      "best/unoptimized: median | worst | best | seeds whose best does not fall |")
print("|---|---|---|---|---|---|---|---|")
for pop, gens in ((4, 10), (16, 20)):
    runs = [json.load(open(f"{out}/p{pop}-g{gens}/seed{s}/run.json")) for s in range(1, n + 1)]
    if any(r["creature"] != creature for r in runs):
        sys.exit(f"seed_table.sh: {out} holds runs of another creature; use another OUT")
    ratios = [r["ratio_best_to_unoptimized"] or 0.0 for r in runs]
    standing = sum(1 for r in runs if not r["best"]["fell"])
    u = runs[0]["unoptimized"]
    fall = f"cycle {u['fall_cycle']}" if u["fell"] else "no fall"
    print(f"| population {pop}, {gens} generations | 1-{n} | {runs[0]['evaluations']} | "
          f"{u['distance']:.2f} ({fall}) | {statistics.median(ratios):.2f}x | {min(ratios):.2f}x | "
          f"{max(ratios):.2f}x | {standing} of {n} |")
PY
