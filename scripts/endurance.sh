#!/usr/bin/env bash
# The endurance study of README.md and docs/results.md ("How long an evolved gait lasts"):
# `hexgait endurance` over the seeds 1-20 sweeps of both budgets (scripts/seed_table.sh runs
# them first when they are missing) and 20 random genomes that stood the test. Writes
# OUT/endurance/ and copies its two figures to docs/images/. About 10 minutes on 2 cores.
#   scripts/endurance.sh [OUT=out/seeds]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/seeds}
hexgait=${HEXGAIT:-build/hexgait}
[ -x "$hexgait" ] || scripts/build.sh
if [ ! -f "$out/hexapod-p4-g10/summary.csv" ] || [ ! -f "$out/hexapod-p16-g20/summary.csv" ]; then
  scripts/seed_table.sh 20 "$out" >/dev/null
fi
"$hexgait" endurance --runs "$out/hexapod-p4-g10" --runs "$out/hexapod-p16-g20" \
  --out "$out/endurance"
cp "$out/endurance/survival.png" docs/images/endurance_survival.png
cp "$out/endurance/paths.png" docs/images/endurance_paths.png
