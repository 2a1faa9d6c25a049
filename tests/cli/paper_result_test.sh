#!/usr/bin/env bash
# The paper's qualitative result with default settings and seed 1: the unoptimised program
# falls by the end of its 4th gait cycle; the evolved one does not fall in 1000 time units
# and walks at least 3 times as far. Run for each built-in creature:
#   paper_result_test.sh HEXGAIT [CREATURE=hexapod]
set -eu
hexgait=$(realpath "$1")
creature=${2:-hexapod}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$hexgait" evolve --seed 1 --creature "$creature" --out "$work/run" --quiet
python3 - "$work/run/run.json" <<'PY'
import json, sys
run = json.load(open(sys.argv[1]))
print(f"creature: {run['creature']}")
u, b = run["unoptimized"], run["best"]
print(f"unoptimized: distance {u['distance']:.3f}, fell {u['fell']}, cycle {u['fall_cycle']}")
print(f"evolved:     distance {b['distance']:.3f}, fell {b['fell']}, ratio {run['ratio_best_to_unoptimized']}")
checks = {
    "unoptimized falls": u["fell"],
    "by the end of its 4th cycle": u["fell"] and u["fall_cycle"] <= 4,
    "evolved does not fall": not b["fell"],
    "evolved walks >= 3x as far": (run["ratio_best_to_unoptimized"] or 0) >= 3.0,
}
failed = [name for name, ok in checks.items() if not ok]
for name in failed:
    print("FAIL:", name)
print(f"{len(checks) - len(failed)} passed, {len(failed)} failed")
sys.exit(1 if failed else 0)
PY
