#!/usr/bin/env bash
# The million-evaluation repertoire of docs/results.md ("A million evaluations"): `hexgait
# repertoire` with 1,000,000 evaluations, seed 1, in float (the precision the million was run
# in; docs/speed.md says why float and what it costs), then every elite replayed in double
# (scripts/replay_archive.py). Prints the machine, /usr/bin/time's wall time and peak memory,
# and copies the map and growth curves to docs/images/. About an hour on 2 idle cores.
# Interrupted (Ctrl-C), it keeps its archive; run it again to resume.
#   scripts/repertoire_million.sh [OUT=out/repertoire_1m] [EVALUATIONS=1000000]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/repertoire_1m}
evaluations=${2:-1000000}
hexgait=${HEXGAIT:-build/hexgait}
[ -x "$hexgait" ] || scripts/build.sh
grep -m1 'model name' /proc/cpuinfo || true
echo "cores: $(nproc)"
resume=()
[ -f "$out/archive.json" ] && [ ! -f "$out/table.md" ] && resume=(--resume "$out")
/usr/bin/time -f 'wall %e s, peak memory %M KB' "$hexgait" repertoire --evaluations "$evaluations" \
  --seed 1 --precision float --allow-long --out "$out" "${resume[@]}"
cp "$out/map.png" docs/images/repertoire_map_1m.png
cp "$out/progress.png" docs/images/repertoire_progress_1m.png
python3 scripts/replay_archive.py "$out/archive.csv" --precision double
