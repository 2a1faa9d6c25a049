#!/usr/bin/env bash
# repertoire: the files it promises, one archive.csv row per filled cell, the same archive on 1
# and 2 threads, a run stopped by Ctrl-C or kill -9 and resumed equal to one never stopped, the
# GA on the same budget, the movie grid, and its refusals.
#   repertoire_test.sh HEXGAIT [ALGORITHM [ITS FLAGS...]]   (default: map-elites)
# The run layer's own rules (two Ctrl-Cs at once, the refusals, an edited archive, flags given
# again with --resume) are the same code for every algorithm: they are checked once, with
# MAP-Elites. Another algorithm's run checks what is its own: its files, its threads, and its
# state resumed to the same bytes after a Ctrl-C and after kill -9.
set -euo pipefail
hexgait="$1"
algorithm="${2:-map-elites}"
shift $(($# < 2 ? $# : 2))
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
source "$(dirname "$0")/../support/signal_ready.sh"

run_layer_rules=$([ "$algorithm" = map-elites ] && echo 1 || true)
flags=(--batch 40 --bins 3 --time 100 --seed 3 --algorithm "$algorithm" "$@")
# The runs that are stopped and resumed: 15 batches, 10 in the sanitizer build (HEXGAIT_SANITIZED,
# set by tests/CMakeLists.txt), which runs several times slower and is stopped as early.
stopped_evaluations=600
[ -z "${HEXGAIT_SANITIZED:-}" ] || stopped_evaluations=400
"$hexgait" repertoire "${flags[@]}" --evaluations 240 --threads 2 --compare-ga 20 --showcase 4 --movie-time 20 \
  --movie-size 320x180 --out "$dir/r2" >"$dir/printed" 2>"$dir/log" || { cat "$dir/log"; fail "run"; }
for f in archive.json archive.csv progress.csv progress.png progress.svg map.csv map.png map.svg \
  table.md repertoire.json grid.mp4 elites/elite-1.genome; do
  [ -s "$dir/r2/$f" ] || fail "$f missing or empty"
done
grep -q "state: complete" "$dir/r2/.hexgait-repertoire" || fail "not marked complete"
filled=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['methods'][0]['filled'])" \
  "$dir/r2/repertoire.json")
rows=$(($(wc -l <"$dir/r2/archive.csv") - 1))
[ "$rows" -eq "$filled" ] || fail "archive.csv has $rows rows, repertoire.json says $filled cells"
[ "$rows" -ge 3 ] || fail "only $rows cells filled"
grep -q "^| paper's GA, population 20 | " "$dir/r2/table.md" || fail "no GA row"
# machine_use: the search's CPU time over its threads' wall time, and lanes that ran creatures.
python3 - "$dir/r2/repertoire.json" <<'PY' || fail "machine_use: $(grep -A12 machine_use "$dir/r2/repertoire.json")"
import json, sys
r = json.load(open(sys.argv[1]))
u = r["machine_use"]
assert 0 < u["cpu_seconds"] <= 1.5 * r["threads"] * u["seconds"], u
lanes = u["lane_steps"]
searched = "float" if r["precision"].startswith("float") else "double"
assert 0 < lanes[searched]["running"] <= lanes[searched]["stepped"], lanes
for kind in ("float", "double"):
    assert 0 <= lanes[kind]["running"] <= lanes[kind]["stepped"], lanes
PY
grep -qF "$(head -n 1 "$dir/r2/table.md")" "$dir/printed" || fail "table not printed"
# An elite replays in simulate with the distance the archive gives it.
line=$(grep -m1 '^| 1 |' "$dir/r2/table.md")
distance=$(echo "$line" | awk -F'|' '{gsub(/ /, "", $5); print $5}')
"$hexgait" simulate --genome "$dir/r2/elites/elite-1.genome" --time 100 --json >"$dir/sim.json"
python3 - "$dir/sim.json" "$distance" <<'PY' || fail "elite-1 does not replay: $line"
import json, sys
r = json.load(open(sys.argv[1]))
assert not r["fell"] and abs(r["distance"] - float(sys.argv[2])) < 0.0005, r["distance"]
PY

"$hexgait" repertoire "${flags[@]}" --evaluations 240 --threads 1 --no-movie --out "$dir/r1" --quiet >/dev/null
cmp "$dir/r1/archive.csv" "$dir/r2/archive.csv" || fail "archive.csv differs between 1 and 2 threads"
cmp <(cut -d, -f1-4 "$dir/r1/map.csv") <(cut -d, -f1-4 "$dir/r2/map.csv") ||
  fail "map.csv differs between 1 and 2 threads"
# Stopped whenever the signal lands, then resumed: the same archive.
"$hexgait" repertoire "${flags[@]}" --evaluations $stopped_evaluations --no-movie --checkpoint-seconds 0.01 \
  --out "$dir/whole" --quiet >/dev/null
# One SIGINT, as a Ctrl-C gives (timeout would send a second one to the process group).
"$hexgait" repertoire "${flags[@]}" --evaluations $stopped_evaluations --no-movie --checkpoint-seconds 0.01 \
  --out "$dir/stopped" --quiet >/dev/null 2>"$dir/stop.log" &
pid=$!
wait_until_catching "$pid" || true  # gone already: the run finished before the signal
# Once a first archive is saved, so the resume has something to continue (a fixed sleep let the
# run finish first on a fast machine, and nothing was tested).
for _ in $(seq 500); do [ -e "$dir/stopped/archive.json" ] && break; sleep 0.01; done
kill -INT "$pid" 2>/dev/null || true
set +e
wait "$pid"
rc=$?
set -e
if [ "$rc" -ne 0 ]; then
  grep -q "hexgait repertoire --resume" "$dir/stop.log" || { cat "$dir/stop.log"; fail "no resume hint"; }
  grep -q "state: running" "$dir/stopped/.hexgait-repertoire" || fail "a stopped run marked complete"
  if "$hexgait" repertoire --resume "$dir/stopped" --seed 4 2>/dev/null; then
    fail "--resume with --seed accepted"
  fi
  "$hexgait" repertoire --resume "$dir/stopped" --no-movie --quiet >/dev/null
fi
cmp "$dir/whole/archive.csv" "$dir/stopped/archive.csv" || fail "resumed archive differs"

# Two SIGINTs at once (Ctrl-C pressed twice): the process ends at once, by the signal, with the
# last archive whole (it is only ever renamed into place), and --resume finishes the same archive.
if [ -n "$run_layer_rules" ]; then
  "$hexgait" repertoire "${flags[@]}" --evaluations $stopped_evaluations --no-movie --checkpoint-seconds 0.01 \
    --out "$dir/twice" --quiet >/dev/null 2>"$dir/twice.log" &
  pid=$!
  wait_until_catching "$pid" || true
  for _ in $(seq 500); do [ -e "$dir/twice/archive.json" ] && break; sleep 0.01; done
  kill -INT "$pid" 2>/dev/null && kill -INT "$pid" 2>/dev/null || true
  set +e
  wait "$pid"
  rc=$?
  set -e
  if [ "$rc" -ne 0 ]; then
    [ "$rc" -eq 130 ] || { cat "$dir/twice.log"; fail "two SIGINTs: exit $rc, expected 130"; }
    "$hexgait" repertoire --resume "$dir/twice" --no-movie --quiet >/dev/null 2>"$dir/twice.log" ||
      { cat "$dir/twice.log"; fail "no whole archive after two SIGINTs"; }
  fi
  cmp "$dir/whole/archive.csv" "$dir/twice/archive.csv" || fail "archive after two SIGINTs differs"
fi

# Killed outright once an archive is saved: --resume continues from it to the same archive.
"$hexgait" repertoire "${flags[@]}" --evaluations $stopped_evaluations --no-movie --checkpoint-seconds 0.01 \
  --out "$dir/killed" --quiet >/dev/null 2>&1 &
pid=$!
for _ in $(seq 500); do [ -e "$dir/killed/archive.json" ] && break; sleep 0.01; done
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
if ! grep -q "state: complete" "$dir/killed/.hexgait-repertoire"; then
  "$hexgait" repertoire --resume "$dir/killed" --no-movie --quiet >/dev/null 2>"$dir/killed.log" ||
    { cat "$dir/killed.log"; fail "no resume after kill -9"; }
fi
cmp "$dir/whole/archive.csv" "$dir/killed/archive.csv" || fail "archive after kill -9 differs"

grep -q "\"algorithm\": \"$algorithm\"" "$dir/r2/repertoire.json" || fail "repertoire.json names no $algorithm"
if [ -z "$run_layer_rules" ]; then
  echo "repertoire ($algorithm): ok"
  exit 0
fi

# Refusals: a folder of other files, a bad descriptor, too many cells, an edited archive.
mkdir "$dir/other" && touch "$dir/other/notes.txt"
if "$hexgait" repertoire "${flags[@]}" --out "$dir/other" 2>"$dir/err"; then fail "foreign folder"; fi
grep -q "not written by hexgait repertoire" "$dir/err" || fail "foreign folder: $(cat "$dir/err")"
if "$hexgait" repertoire --descriptor speed --out "$dir/x" 2>"$dir/err"; then fail "descriptor"; fi
grep -q "unknown" "$dir/err" || fail "descriptor: $(cat "$dir/err")"
if "$hexgait" repertoire --bins 11 --out "$dir/x" 2>"$dir/err"; then fail "bins"; fi
sed -i 's/"seed": "3"/"seed": "8"/' "$dir/r1/archive.json"
printf "state: running\n" >"$dir/r1/.hexgait-repertoire"
if "$hexgait" repertoire --resume "$dir/r1" 2>"$dir/err"; then fail "edited archive resumed"; fi
grep -q "checksum" "$dir/err" || fail "edited archive: $(cat "$dir/err")"
# An elite's result edited and the checksum recomputed (anyone can): the replay on resume finds
# it; the unedited archive resumes and says how many elites it replayed.
"$hexgait" repertoire "${flags[@]}" --evaluations 80 --no-movie --out "$dir/edit" --quiet >/dev/null
printf "state: running\n" >"$dir/edit/.hexgait-repertoire"
cp "$dir/edit/archive.json" "$dir/archive.orig"
python3 "$(dirname "$0")/../support/edit_archive_elite.py" "$dir/edit/archive.json"
if "$hexgait" repertoire --resume "$dir/edit" --no-movie 2>"$dir/err" >/dev/null; then
  fail "an archive with an edited elite was resumed"
fi
grep -q "does not replay to its stored result (distance" "$dir/err" || fail "edited elite: $(cat "$dir/err")"
cp "$dir/archive.orig" "$dir/edit/archive.json"
"$hexgait" repertoire --resume "$dir/edit" --no-movie >"$dir/printed" 2>&1 || { cat "$dir/printed"; fail "resume"; }
grep -q "checked the archive: replayed all [0-9]* stored elites: every result matches" "$dir/printed" ||
  fail "no replay line: $(head -3 "$dir/printed")"
# A resumed run writes what it was started for (the folder's outputs.json): its --no-movie is
# kept; a flag given again with --resume changes that choice and is recorded.
printf "state: running\n" >"$dir/edit/.hexgait-repertoire"
"$hexgait" repertoire --resume "$dir/edit" --compare-ga 4 >"$dir/printed" 2>&1 || { cat "$dir/printed"; fail "resume"; }
[ ! -e "$dir/edit/grid.mp4" ] || fail "--resume rendered the movie grid of a --no-movie run"
grep -q "comparison: the paper's GA, population 4" "$dir/printed" || fail "--resume ignored --compare-ga"
grep -q '"--compare-ga": 4' "$dir/edit/outputs.json" || fail "outputs.json: $(cat "$dir/edit/outputs.json")"
grep -q '"--no-movie": true' "$dir/edit/outputs.json" || fail "outputs.json: $(cat "$dir/edit/outputs.json")"
[ ! -e "$dir/x" ] || fail "a refused run left a folder"
echo "repertoire ($algorithm): ok"
