#!/usr/bin/env bash
# The repertoire's precision, measured (docs/speed.md, "The repertoire's precision"): the same
# repertoire (seed 1, no movie, both threads) in double, in float with its admissions confirmed
# in double (--precision auto, the default) and in float alone (--no-confirm), RUNS times each
# in turns, with /usr/bin/time's wall time; prints the median of each and its ratio to double,
# then replays both float runs' elites in double (scripts/replay_archive.py): how many of the
# gaits each map shows still stand in 'simulate' and the movie, which replay in double.
#   scripts/repertoire_precision.sh [EVALUATIONS=10000] [RUNS=3] [WORK=a temporary folder]
# Environment: HEXGAIT (default build/hexgait), MODES (default "double confirmed float": a
# subset times only those, e.g. MODES="confirmed float" for what confirming costs).
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
read -r -a modes <<< "${MODES:-double confirmed float}"
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
args=()
for mode in "${modes[@]}"; do args+=("$mode" "${times[$mode]}"); done
python3 - "$evaluations" "${args[@]}" <<'PY'
import statistics, sys
n = int(sys.argv[1])
names = {"double": "double", "confirmed": "float, confirmed in double", "float": "float alone"}
medians = {m: statistics.median(float(t) for t in ts.split())
           for m, ts in zip(sys.argv[2::2], sys.argv[3::2])}
base = "double" if "double" in medians else next(iter(medians))
for mode, m in medians.items():
    print(f"{names[mode]:27} median {m:.2f} s, {n / m:.0f} evaluations/s, "
          f"{medians[base] / m:.2f}x {names[base]}")
PY
for mode in "${modes[@]}"; do
  echo "$mode: $(tail -n +2 "$work/$mode/archive.csv" | wc -l) cells"
done
for mode in "${modes[@]}"; do
  [ "$mode" = double ] && continue
  echo "the $mode run's elites replayed in double:"
  python3 scripts/replay_archive.py "$work/$mode/archive.csv" --precision double
done
if [ -f "$work/confirmed/archive.json" ]; then
  python3 - "$work/confirmed/archive.json" <<'PY'
import json, sys
last = json.load(open(sys.argv[1]))["history"][-1]
print(f"confirmed run: {last['confirmed']} children run again in double, "
      f"{last['refuted']} of them kept out")
PY
fi
