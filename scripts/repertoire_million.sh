#!/usr/bin/env bash
# The million-evaluation repertoire of docs/results.md ("A million evaluations"): `hexgait
# repertoire` with 1,000,000 evaluations, seed 1, with the default precision (float with its
# admissions confirmed in double), or with MODE float in float alone (--no-confirm: how the
# first million was run), with --no-movie (the time is the search's), then every elite replayed in
# double (scripts/replay_archive.py).
# Prints the machine, /usr/bin/time's wall time, CPU time and peak memory (CPU time over cores x
# wall time: how busy the run kept the machine), and copies the map and growth
# curves to docs/images/ (repertoire_map_1m.png, or _1m_float.png for MODE float). 57 minutes
# on the 2-core Zen 5, 81 on the Zen 4 (docs/results.md, "A million evaluations").
# Interrupted (Ctrl-C), it keeps its archive; run it again to resume.
#   scripts/repertoire_million.sh [OUT=out/repertoire_1m] [EVALUATIONS=1000000] [MODE=confirmed]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/repertoire_1m}
evaluations=${2:-1000000}
hexgait=${HEXGAIT:-build/hexgait}
[ -x "$hexgait" ] || scripts/build.sh
grep -m1 'model name' /proc/cpuinfo || true
echo "cores: $(nproc)"
mode=${3:-confirmed}
case $mode in
  confirmed) precision=(--precision auto) suffix= ;;
  float) precision=(--precision float --no-confirm) suffix=_float ;;
  *) echo "scripts/repertoire_million.sh: MODE must be confirmed or float, not '$mode'" >&2; exit 2 ;;
esac
if [ -f "$out/archive.json" ] && [ ! -f "$out/table.md" ]; then
  args=(--resume "$out")  # the archive holds the run's settings
else
  args=(--evaluations "$evaluations" --seed 1 "${precision[@]}" --no-movie --out "$out")
fi
/usr/bin/time -f 'wall %e s, CPU %U s user + %S s system, peak memory %M KB' "$hexgait" repertoire --allow-long "${args[@]}"
cp "$out/map.png" "docs/images/repertoire_map_1m$suffix.png"
cp "$out/progress.png" "docs/images/repertoire_progress_1m$suffix.png"
/usr/bin/python3 scripts/replay_archive.py "$out/archive.csv" --precision double
