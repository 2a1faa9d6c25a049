#!/usr/bin/env bash
# 'hexgait adapt' end to end: a small repertoire, a damage, every promised file, the trials
# agreeing with adapt.json, the same bytes on 1 and 2 threads (with --library too), a second run replacing the
# first folder whole, and the movie's GL backend checked before the work.
# Usage: adapt_test.sh HEXGAIT
set -eu
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# Gaits of 300 time units; 150 in the sanitizer build (HEXGAIT_SANITIZED, set by
# tests/CMakeLists.txt), where every trial, random elite and GA run costs several times more.
gait_time=300
[ -z "${HEXGAIT_SANITIZED:-}" ] || gait_time=150

"$hexgait" repertoire --evaluations 200 --batch 50 --time $gait_time --no-movie --compare-ga 0 --quiet \
  --out "$work/rep" >/dev/null
"$hexgait" adapt --repertoire "$work/rep" --damage left_rear:weak=0.2 --threads 2 \
  --movie-time 10 --movie-size 320x240 --out "$work/a" >"$work/log"
for f in trials.csv elites.csv adapt.json adapted.genome adapt.png adapt.svg adapt.csv adapt.gp \
         adapt.mp4; do
  [ -s "$work/a/$f" ] || fail "no $f"
done
trials=$(($(wc -l <"$work/a/trials.csv") - 1))
grep -q "\"trials\": $trials," "$work/a/adapt.json" || fail "adapt.json does not say $trials trials"
[ "$trials" -ge 1 ] && [ "$trials" -le 20 ] || fail "$trials trials"
elites=$(($(wc -l <"$work/a/elites.csv") - 1))
grep -q "\"elites\": $elites," "$work/a/adapt.json" || fail "elites.csv has $elites rows"
grep -Eq "after $trials trials?: adapted gait walks" "$work/log" || fail "$(cat "$work/log")"
# The adapted genome replays: simulate on the damaged creature gives the best trial's distance
# (a trial ends at a fall, as the repertoire's runs do; simulate runs on, so only a gait that
# stands is compared).
best=$(tail -1 "$work/a/trials.csv" | cut -d, -f7)
"$hexgait" simulate --genome "$work/a/adapted.genome" --damage left_rear:weak=0.2 --time $gait_time \
  --json >"$work/sim.json"
python3 - "$work/sim.json" "$best" <<'PY' || fail "adapted.genome does not replay its trial"
import json, sys
result = json.load(open(sys.argv[1]))
assert result["fell"] or abs(result["distance"] - float(sys.argv[2])) < 1e-9, result["distance"]
PY
# Deterministic whatever the thread count; a second run replaces the folder.
"$hexgait" adapt --repertoire "$work/rep" --damage left_rear:weak=0.2 --threads 1 --no-movie \
  --out "$work/a" >/dev/null
for f in trials.csv elites.csv adapted.genome; do
  [ -s "$work/a/$f" ] || fail "no $f after the second run"
done
[ ! -e "$work/a/adapt.mp4" ] || fail "the second run kept the first run's movie"
"$hexgait" adapt --repertoire "$work/rep" --damage left_rear:weak=0.2 --threads 2 --no-movie \
  --out "$work/b" >/dev/null
cmp -s "$work/a/trials.csv" "$work/b/trials.csv" || fail "trials differ between 1 and 2 threads"
cmp -s "$work/a/elites.csv" "$work/b/elites.csv" || fail "elites differ between 1 and 2 threads"
# With --library too, whose runs at the tried elites run side by side, one per thread (on 1
# thread as well outside the sanitizer build, where each run costs several times more).
threads="2"
[ -n "${HEXGAIT_SANITIZED:-}" ] || threads="1 2"
for t in $threads; do
  "$hexgait" adapt --repertoire "$work/rep" --damage left_rear:weak=0.2 --threads $t --no-movie \
    --library --out "$work/l$t" >/dev/null
done
[ -n "${HEXGAIT_SANITIZED:-}" ] || cmp -s "$work/l1/trials.csv" "$work/l2/trials.csv" ||
  fail "--library's trials differ between 1 and 2 threads"
# --no-stop runs every trial; its first trials are the stopped run's, and adapt.json says where
# the rule stopped that run, with its comparisons there (the same as the stopped run's).
"$hexgait" adapt --repertoire "$work/rep" --damage left_rear:weak=0.2 --threads 2 --no-movie \
  --trials 20 --no-stop --out "$work/n" >/dev/null
python3 - "$work/b" "$work/n" <<'PY' || fail "--no-stop does not continue the stopped run"
import csv, json, sys
stopped, full = (json.load(open(d + "/adapt.json")) for d in sys.argv[1:])
rows = [list(csv.reader(open(d + "/trials.csv")))[1:] for d in sys.argv[1:]]
assert full["trials"] == 20 and len(rows[1]) == 20, full["trials"]
assert rows[1][:len(rows[0])] == rows[0], "the first trials differ"
assert "at_stop_rule" not in stopped
if stopped["stopped"].startswith("the best trial reached"):
    at = full["at_stop_rule"]
    assert at["trials"] == stopped["trials"], (at, stopped["trials"])
    assert at["adapted"] == stopped["adapted"]["distance"]
    assert at["random_elites_best"] == stopped["random_elites"]["best"]
    assert at["ga_from_intact_best"] == stopped["ga_from_intact_best"]["best"]
else:
    assert full["at_stop_rule"] is None
PY
grep -q "checked the archive: replayed all $elites stored elites: every result matches" "$work/log" ||
  fail "no replay of the archive: $(head -3 "$work/log")"
# The prior is replayed, not trusted: an elite's distance edited and the checksum recomputed
# (anyone can) is found.
cp -r "$work/rep" "$work/edited"
python3 "$(dirname "$0")/../support/edit_archive_elite.py" "$work/edited/archive.json"
if "$hexgait" adapt --repertoire "$work/edited" --damage left_rear:weak=0.2 --no-movie \
  --out "$work/e" >/dev/null 2>"$work/err"; then
  fail "adapt trusted an edited elite"
fi
grep -q "does not replay to its stored result (distance" "$work/err" || fail "edited elite: $(cat "$work/err")"
[ ! -e "$work/e" ] || fail "a refused adapt left a folder"
# So is --out: a folder in a file is refused before the work (it was found after the trials).
touch "$work/afile"
if "$hexgait" adapt --repertoire "$work/rep" --damage left_rear:weak=0.2 --no-movie \
  --out "$work/afile/a" >"$work/log" 2>"$work/err"; then
  fail "adapt into a file's folder succeeded"
fi
grep -q "'$work/afile' is a file, not a folder" "$work/err" || fail "$(cat "$work/err")"
[ ! -s "$work/log" ] || fail "adapt ran before finding its --out unusable: $(head -2 "$work/log")"
# The movie's GL backend is checked before the first simulation, not after the trials.
if HEXGAIT_GL=vulkan "$hexgait" adapt --repertoire "$work/rep" --damage left_rear:weak=0.2 \
  --out "$work/c" >"$work/log" 2>"$work/err"; then
  fail "adapt with no GL backend succeeded"
fi
grep -q "unknown backend 'vulkan'" "$work/err" || fail "$(cat "$work/err")"
[ ! -s "$work/log" ] || fail "adapt ran its trials before finding it cannot draw the movie: $(head -2 "$work/log")"
[ ! -e "$work/c" ] || fail "adapt with no GL backend left a folder"
echo "adapt checked: $trials trials over $elites elites"
