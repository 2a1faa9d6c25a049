#!/usr/bin/env bash
# A run's scene travels with its folder: a run evolved on a damaged creature, with another step,
# is replayed, filmed, tested for endurance and drawn on that creature with that step by
# `replay --run`, `movie --run`, `endurance --run` and `figures --run` (each gives the distance
# `simulate` gives with the run's own flags, not the intact creature's); a flag that contradicts
# the record is refused; a creature file edited after the run is refused; `report` refuses
# folders of two scenes.
# Usage: folder_scene_test.sh HEXGAIT ASSETS_DIR
set -euo pipefail
hexgait=$(realpath "$1")
assets=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

damage=right_front:weak=0.3,left_rear:locked
scene=(--damage "$damage" --dt 0.003)
"$hexgait" evolve --seed 2 --generations 1 --time 120 "${scene[@]}" --quiet --out "$work/run" \
  >/dev/null
distance() {  # simulate's distance of the run's genome over 120 time units, with FLAGS
  "$hexgait" simulate --genome "$work/run/best.genome" --time 120 "$@" --json |
    python3 -c 'import json, sys; print(repr(json.load(sys.stdin)["distance"]))'
}
own=$(distance "${scene[@]}")
intact=$(distance)
[ "$own" != "$intact" ] || fail "the damage does not change the distance ($own): the test shows nothing"

# replay: the page's run is the run's own.
"$hexgait" replay --run "$work/run" --time 120 --out "$work/r.html" >/dev/null
python3 - "$work/r.html" "$own" <<'PY' || fail "replay --run does not replay the run's scene"
import json, re, sys
page = open(sys.argv[1]).read()
run = re.search(r'"run":(\{[^{}]*\})', page)
assert run, "no run in the page"
got = json.loads(run.group(1))
assert repr(got["distance"]) == sys.argv[2] and got["dt"] == 0.003, (got, sys.argv[2])
PY
grep -q '<title>hexgait replay: [^<]*(damaged (red): [^<]*right_front:weak=0.3' "$work/r.html" ||
  fail "the replay page's title does not name the damage"

# What the commands print names the damage.
"$hexgait" simulate --genome "$work/run/best.genome" --time 10 "${scene[@]}" >"$work/sim.txt"
grep -q "^damage  *right_front:weak=0.3" "$work/sim.txt" || fail "simulate does not name the damage"
"$hexgait" still --size 64x48 "${scene[@]}" --out "$work/still.png" >"$work/still.txt"
grep -q "damaged: right_front:weak=0.3" "$work/still.txt" || fail "still does not name the damage"

# movie: the evolved movie's run is the run's own (printed to 2 decimals).
"$hexgait" movie --run "$work/run" --time 120 --size 160x120 --out "$work/m" >"$work/movie.log"
want=$(printf 'evolved distance %.2f' "$own")
grep -qF "$want" "$work/movie.log" || fail "movie --run: '$want' not in: $(tail -1 "$work/movie.log")"

# figures: the evolved program's run is the run's own. (Its --out spelled DIR/. and endurance's
# DIR/ name the same folders: checked and written in one spelling.)
"$hexgait" figures --run "$work/run" --time 120 --no-figure1 --out "$work/f/." >/dev/null
python3 - "$work/f/figures.json" "$own" <<'PY' || fail "figures --run does not use the run's scene"
import json, sys
got = json.load(open(sys.argv[1]))["programs"]["evolved"]["distance"]
assert repr(got) == sys.argv[2], (got, sys.argv[2])
PY

# report: the page of a run evolved damaged names the damage in its title and heading.
"$hexgait" report --run "$work/run" --movies "$work/m" --figures "$work/f" --out "$work/page" \
  >/dev/null
grep -q '<title>hexgait: evolving legged locomotion, seed 2 (damaged (red): right_front:weak=0.3' \
  "$work/page/index.html" || fail "the report's title does not name the damage"

# endurance: the gait's test is the run's own. (--random 0: no search for random genomes that
# stand, 3 s of the command's 3.6 in the release build and most of its 18.6 s sanitized.)
"$hexgait" endurance --run "$work/run" --time 120 --long 2 --horizon 2 --trials 1 --random 0 --quiet \
  --out "$work/e/" >/dev/null
python3 - "$work/e/endurance.json" "$own" <<'PY' || fail "endurance --run does not use the run's scene"
import json, sys
record = json.load(open(sys.argv[1]))
gaits = record["gaits"]
assert repr(gaits[0]["test"]["distance"]) == sys.argv[2], (gaits[0], sys.argv[2])
assert "right_front:weak=0.3" in record["damage"] and record["dt"] == 0.003, record
PY

# A flag that says what the record says is accepted; one that contradicts it is refused.
"$hexgait" replay --run "$work/run" --time 10 --dt 0.003 --damage "$damage" \
  --out "$work/same.html" >/dev/null || fail "flags equal to the record are refused"
expect_refused() {  # MESSAGE ARGS...: exit 1, the message, nothing written
  local message=$1
  shift
  if "$hexgait" "$@" >"$work/out" 2>"$work/err"; then fail "accepted: $*"; fi
  grep -qF -- "$message" "$work/err" || fail "$*: expected '$message', got: $(cat "$work/err")"
}
expect_refused "--dt 0.0025 contradicts --run '$work/run', made with --dt 0.003" \
  replay --run "$work/run" --dt 0.0025 --out "$work/x.html"
expect_refused "--damage 'left_rear:locked' contradicts --run" \
  movie --run "$work/run" --damage left_rear:locked --out "$work/m2"
expect_refused "--integrator verlet contradicts --run" \
  figures --run "$work/run" --integrator verlet --no-figure1 --out "$work/f2"
expect_refused "--creature 'wedge' contradicts --run" \
  endurance --run "$work/run" --creature wedge --out "$work/e2"
[ ! -e "$work/x.html" ] && [ ! -e "$work/m2" ] && [ ! -e "$work/f2" ] && [ ! -e "$work/e2" ] ||
  fail "a refused command wrote something"

# A folder that is not there, a file, a folder without a record.
expect_refused "--run '$work/none': no such folder" endurance --run "$work/none" --out "$work/e4"
expect_refused "is a file, not a folder" movie --run "$work/run/run.json" --out "$work/m4"
mkdir "$work/empty"
expect_refused "no run.json, archive.json or adapt.json there, so nothing says which scene made it" \
  endurance --run "$work/empty" --out "$work/e5"

# Two folders of different scenes are refused together.
"$hexgait" evolve --seed 3 --generations 1 --time 120 --quiet --out "$work/intact" >/dev/null
expect_refused "was made on another scene than --run '$work/run'" \
  endurance --run "$work/run" --run "$work/intact" --out "$work/e3"

# One report page, one animal: a repertoire, or an adaptation (adapt.json keeps its repertoire's
# scene), of the wedge beside a hexapod run is refused, naming both folders, before any page.
"$hexgait" repertoire --creature wedge --evaluations 40 --batch 20 --time 50 --no-movie \
  --compare-ga 0 --quiet --out "$work/wedge_rep" >/dev/null
"$hexgait" adapt --repertoire "$work/wedge_rep" --damage left_rear:weak=0.5 --no-movie \
  --out "$work/wedge_adapt" >/dev/null
python3 - "$work/wedge_adapt/adapt.json" <<'PY' || fail "adapt.json does not record its scene"
import json, sys
scene = json.load(open(sys.argv[1]))["scene"]
assert scene["creature"] == "wedge" and len(scene["scene_fingerprint"]) > 8, scene
PY
expect_refused "--repertoire '$work/wedge_rep' was made on another scene than --run '$work/intact'" \
  report --run "$work/intact" --repertoire "$work/wedge_rep" --out "$work/report1"
expect_refused "--adapt '$work/wedge_adapt' was made on another scene than --run '$work/intact'" \
  report --run "$work/intact" --adapt "$work/wedge_adapt" --out "$work/report2"
[ ! -e "$work/report1" ] && [ ! -e "$work/report2" ] || fail "a refused report wrote something"

# A creature file edited after the run is refused by its fingerprint.
cp "$assets/hexapod.json" "$work/c.json"
"$hexgait" evolve --seed 2 --generations 1 --time 60 --creature "$work/c.json" --quiet \
  --out "$work/filed" >/dev/null
"$hexgait" replay --run "$work/filed" --time 10 --out "$work/filed.html" >/dev/null ||
  fail "a run of a creature file does not replay"
sed -i 's/"gravity": *[0-9.]*/"gravity": 9.5/' "$work/c.json"
expect_refused "was made with a different creature or motor program" \
  replay --run "$work/filed" --time 10 --out "$work/edited.html"
echo "folder scenes: replay, movie, figures and endurance use the run's own scene; report one scene"
