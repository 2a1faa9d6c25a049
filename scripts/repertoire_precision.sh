#!/usr/bin/env bash
# The repertoire's precision, measured (docs/speed.md, "The repertoire's precision"): the same
# repertoire (seed 1, no movie, both threads) in double, in float with its admissions confirmed
# in double (--precision auto, the default) and in float alone (--no-confirm), RUNS times each
# in turns, with /usr/bin/time's wall time; prints the median of each and its ratio to double,
# then replays both float runs' elites in double (scripts/replay_archive.py): how many of the
# gaits each map shows still stand in 'simulate' and the movie, which replay in double.
#   scripts/repertoire_precision.sh [EVALUATIONS=10000] [RUNS=3] [WORK=a temporary folder]
set -euo pipefail
cd "$(dirname "$0")/.."
evaluations=${1:-10000}
runs=${2:-3}
work=${3:-$(mktemp -d)}
hexgait=${HEXGAIT:-build/hexgait}
[ -x "$hexgait" ] || scripts/build.sh
grep -m1 'model name' /proc/cpuinfo || true
echo "cores: $(nproc); $evaluations evaluations, $runs runs of each mode in turns"
mkdir -p "$work"
modes=(double confirmed float)
declare -A flags=([double]="--precision double" [confirmed]="--precision auto"
  [float]="--precision float --no-confirm")
declare -A times
for ((r = 1; r <= runs; r++)); do
  for mode in "${modes[@]}"; do
    rm -rf "${work:?}/$mode"
    # shellcheck disable=SC2086
    /usr/bin/time -f '%e' -o "$work/time" "$hexgait" repertoire --evaluations "$evaluations" \
      --seed 1 --no-movie --quiet ${flags[$mode]} --out "$work/$mode" >/dev/null
    times[$mode]+="$(cat "$work/time") "
    echo "run $r, $mode: $(cat "$work/time") s"
  done
done
python3 - "$evaluations" "${times[double]}" "${times[confirmed]}" "${times[float]}" <<'PY'
import statistics, sys
n = int(sys.argv[1])
medians = [statistics.median(float(t) for t in arg.split()) for arg in sys.argv[2:]]
names = ["double", "float, confirmed in double", "float alone"]
for name, m in zip(names, medians):
    print(f"{name:27} median {m:.2f} s, {n / m:.0f} evaluations/s, {medians[0] / m:.2f}x double")
PY
for mode in "${modes[@]}"; do
  echo "$mode: $(tail -n +2 "$work/$mode/archive.csv" | wc -l) cells"
done
for mode in confirmed float; do
  echo "the $mode run's elites replayed in double:"
  python3 scripts/replay_archive.py "$work/$mode/archive.csv" --precision double
done
python3 - "$work/confirmed/archive.json" <<'PY'
import json, sys
last = json.load(open(sys.argv[1]))["history"][-1]
print(f"confirmed run: {last['confirmed']} children run again in double, "
      f"{last['refuted']} of them kept out")
PY
