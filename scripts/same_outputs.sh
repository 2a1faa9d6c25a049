#!/usr/bin/env bash
# Whether two hexgait binaries write the same outputs for the searches: the GA with the paper's
# settings for seeds 1-3, a --symmetric run, and a 2,000-evaluation repertoire (MAP-Elites); and
# for the pictures of an intact creature (Figure 1, a still, a filmstrip, a movie, a replay page).
# fitness.csv, best.genome, archive.csv and the elites must be the same bytes; the JSON files
# (run.json, checkpoint.json, archive.json, repertoire.json) the same apart from wall times,
# thread counts, how busy a run kept the machine (repertoire.json's machine_use), the checksums
# over them, and where the hexgait version is recorded (a
# checkpoint's or archive's format version counts the same under "format_version" and, as older
# files name it, "version"); table.md apart from its wall-time column. A JSON key only the new
# binary writes is named and not compared.
#
#   scripts/same_outputs.sh OLD_HEXGAIT NEW_HEXGAIT [WORK_DIR]
#
# For a restructuring: build the commit before it into another folder (git worktree), then run
# this with both binaries. Exit 1, naming the file, on any difference.
set -euo pipefail
[ $# -ge 2 ] || { sed -n 2,13p "$0"; exit 2; }
old=$(realpath "$1")
new=$(realpath "$2")
work=${3:-$(mktemp -d)}
# One genome file for both binaries: the pictures' captions name it.
genome=$(realpath "$(dirname "$0")/../tests/data/evolved_seed1.genome")
mkdir -p "$work"
run() {
  local hexgait=$1 out=$2
  rm -rf "$out"
  for seed in 1 2 3; do "$hexgait" evolve --seed "$seed" --quiet --out "$out/ga-$seed"; done
  "$hexgait" evolve --seed 4 --symmetric --quiet --out "$out/symmetric"
  "$hexgait" repertoire --seed 1 --evaluations 2000 --batch 250 --precision double --no-movie --quiet \
    --out "$out/repertoire" > /dev/null
  # The pictures of an intact creature, each compared byte for byte: Figure 1, a still of the
  # evolved gait, a filmstrip, a short movie with every cue, and a replay page.
  mkdir -p "$out/pictures"
  "$hexgait" still --out "$out/pictures/figure1.png" > /dev/null
  "$hexgait" still --genome "$genome" --time 200 --size 320x240 --out "$out/pictures/still.png" \
    > /dev/null
  "$hexgait" filmstrip --genome "$genome" --size 160x120 --out "$out/pictures/filmstrip.png" \
    > /dev/null
  "$hexgait" render --genome "$genome" --time 60 --size 320x240 --cues all \
    --out "$out/pictures/gait.mp4" > /dev/null
  "$hexgait" replay --genome "$genome" --time 100 --out "$out/pictures/replay.html" > /dev/null
}
run "$old" "$work/old"
run "$new" "$work/new"
status=0
while IFS= read -r file; do
  case "$file" in
    *.json)
      /usr/bin/python3 - "$work/old/$file" "$work/new/$file" <<'PY' || { echo "differs: $file"; status=1; }
import json, sys
TIMING = {"seconds", "wall_seconds", "seconds_per_evaluation", "checksum", "threads",
          "machine_use", "hexgait_version"}
def strip(o):
    if isinstance(o, dict):
        return {k: strip(v) for k, v in o.items() if k not in TIMING}
    if isinstance(o, list):
        return [strip(v) for v in o]
    return o
def load(path):
    data = json.load(open(path))
    if isinstance(data, dict) and isinstance(data.get("version"), str):
        del data["version"]  # the program's version, before it was "hexgait_version"
    if isinstance(data, dict) and isinstance(data.get("version"), int):
        data["format_version"] = data.pop("version")  # a checkpoint's format, as older files name it
    return strip(data)
def added(old, new, where=""):
    # Keys the new binary records that the old did not (a round that records more): named, not
    # compared. Every key the old one wrote must still be there with the same value.
    if isinstance(old, dict) and isinstance(new, dict):
        for k in list(new):
            if k not in old:
                print(f"  note: {sys.argv[2]}: new key {where}{k}", file=sys.stderr)
                del new[k]
            else:
                added(old[k], new[k], f"{where}{k}.")
a, b = (load(p) for p in sys.argv[1:3])
added(a, b)
sys.exit(0 if a == b else 1)
PY
      ;;
    ./pictures/*) cmp -s "$work/old/$file" "$work/new/$file" || { echo "differs: $file"; status=1; } ;;
    *.png | *.svg) ;;  # drawn by gnuplot from the CSV files compared here
    *.md)  # the table's last column is the wall time
      cmp -s <(sed 's/| [0-9.]* min |$/|/' "$work/old/$file") \
        <(sed 's/| [0-9.]* min |$/|/' "$work/new/$file") || { echo "differs: $file"; status=1; } ;;
    *) cmp -s "$work/old/$file" "$work/new/$file" || { echo "differs: $file"; status=1; } ;;
  esac
done < <(cd "$work/old" && find . -type f | sort)
[ "$status" = 0 ] &&
  echo "same outputs: GA seeds 1-3, symmetric, repertoire of 2,000, pictures of an intact creature ($work)"
exit "$status"
