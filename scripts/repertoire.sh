#!/usr/bin/env bash
# The repertoire of docs/results.md ("A repertoire of gaits"): `hexgait
# repertoire` with 100,000 evaluations, seed 1, and the paper's GA (population 100) on the same
# budget, in double (the precision that run was made in, before float with confirmed
# admissions became the default); prints the machine and /usr/bin/time's wall time and peak memory, and copies the map,
# the growth curves and a frame of the movie grid to docs/images/. About 35 minutes on 2 cores
# (MAP-Elites alone: about half).
#   scripts/repertoire.sh [OUT=out/repertoire] [EVALUATIONS=100000]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/repertoire}
evaluations=${2:-100000}
hexgait=${HEXGAIT:-build/hexgait}
[ -x "$hexgait" ] || scripts/build.sh
grep -m1 'model name' /proc/cpuinfo || true
echo "cores: $(nproc)"
/usr/bin/time -f 'wall %e s, peak memory %M KB' "$hexgait" repertoire --evaluations "$evaluations" \
  --seed 1 --precision double --compare-ga 100 --out "$out"
cp "$out/map.png" docs/images/repertoire_map.png
cp "$out/progress.png" docs/images/repertoire_progress.png
# A frame of the movie grid four gait cycles in (one cycle per second of video).
ffmpeg -loglevel error -y -ss 4 -i "$out/grid.mp4" -frames:v 1 -vf scale=1280:-2 \
  docs/images/repertoire_grid.png
