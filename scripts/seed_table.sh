#!/usr/bin/env bash
# The seeds tables of docs/results.md ("Seeds 1-20"): `hexgait sweep` over seeds 1..N with the
# paper's budget (population 4, 10 generations) and a larger one (population 16, 20 generations:
# 316 evaluations, 9x the paper's), printing the Markdown table. The larger budget takes a
# while (about 10 minutes on 2 cores); progress goes to stderr, and a second call keeps the
# seeds already run. Under MPI, put mpirun in front: MPIRUN="mpirun -np 8" scripts/seed_table.sh.
# CREATURE picks a built-in creature (default: hexapod).
#   [CREATURE=wedge] [MPIRUN=...] scripts/seed_table.sh [N=20] [OUT=out/seeds]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-20}
out=${2:-out/seeds}
hexgait=${HEXGAIT:-build/hexgait}
creature=${CREATURE:-hexapod}
read -r -a mpirun <<<"${MPIRUN:-}"
[ -x "$hexgait" ] || scripts/build.sh
header_printed=0
for budget in "4 10" "16 20"; do
  set -- $budget
  table=$("${mpirun[@]}" "$hexgait" sweep --seeds "1-$n" --population "$1" --generations "$2" \
    --creature "$creature" --out "$out/$creature-p$1-g$2")
  if [ "$header_printed" -eq 0 ]; then
    echo "$table"
    header_printed=1
  else
    echo "$table" | tail -n 1
  fi
done
