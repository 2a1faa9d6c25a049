#!/usr/bin/env bash
# The repertoire's precision, measured (docs/speed.md, "The repertoire's precision"): the same
# repertoire (seed 1, no movie, both threads) in double and in float, RUNS times each in turns,
# with /usr/bin/time's wall time; prints the median of each and their ratio, then replays the
# float run's elites in double (scripts/replay_archive.py): how many of the gaits its map shows
# still stand in 'simulate' and the movie, which replay in double.
#   scripts/repertoire_precision.sh [EVALUATIONS=20000] [RUNS=3] [WORK=a temporary folder]
set -euo pipefail
cd "$(dirname "$0")/.."
evaluations=${1:-20000}
runs=${2:-3}
work=${3:-$(mktemp -d)}
hexgait=${HEXGAIT:-build/hexgait}
[ -x "$hexgait" ] || scripts/build.sh
grep -m1 'model name' /proc/cpuinfo || true
echo "cores: $(nproc); $evaluations evaluations, $runs runs of each precision in turns"
mkdir -p "$work"
declare -A times
for ((r = 1; r <= runs; r++)); do
  for precision in double float; do
    rm -rf "$work/$precision"
    /usr/bin/time -f '%e' -o "$work/time" "$hexgait" repertoire --evaluations "$evaluations" \
      --seed 1 --no-movie --quiet --precision "$precision" --out "$work/$precision" >/dev/null
    times[$precision]+="$(cat "$work/time") "
    echo "run $r, $precision: $(cat "$work/time") s"
  done
done
python3 - "${times[double]}" "${times[float]}" "$evaluations" <<'PY'
import statistics, sys
double = statistics.median(float(t) for t in sys.argv[1].split())
single = statistics.median(float(t) for t in sys.argv[2].split())
n = int(sys.argv[3])
print(f"double: median {double:.2f} s, {n / double:.0f} evaluations/s")
print(f"float:  median {single:.2f} s, {n / single:.0f} evaluations/s")
print(f"float is {double / single:.2f}x as fast")
PY
for precision in double float; do
  echo "$precision: $(tail -n +2 "$work/$precision/archive.csv" | wc -l) cells"
done
echo "the float run's elites replayed in double:"
python3 scripts/replay_archive.py "$work/float/archive.csv" --precision double
