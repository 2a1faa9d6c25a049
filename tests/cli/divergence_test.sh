#!/usr/bin/env bash
# A diverged simulation is its own outcome in every command's tables, never folded into "fell"
# or "did not fall": evolve (fitness.csv, the closing lines), sweep (summary.csv, table.md),
# repertoire (table.md, progress.csv, repertoire.json), endurance (table.md) and figures (which
# names the divergence instead of a misleading zero). A step of 0.012 (explicit Euler) diverges
# the hexapod within the first gait cycle; 0.05 does so before it can fall.
set -euo pipefail
hexgait="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$hexgait" evolve --dt 0.012 --population 6 --generations 2 --time 100 --out "$dir/run" >"$dir/printed"
grep -q "^16 of the 16 evaluations diverged" "$dir/printed" || fail "evolve: $(tail -3 "$dir/printed")"
grep -q "^unoptimized .* diverged$" "$dir/printed" || fail "evolve: unoptimized not called diverged"
[ "$(head -n 1 "$dir/run/fitness.csv")" = "generation,best,mean,worst,diverged" ] || fail "fitness.csv header"
[ "$(cut -d, -f5 "$dir/run/fitness.csv" | tail -n +2 | paste -sd+ | bc)" -eq 16 ] || fail "fitness.csv count"

if "$hexgait" figures --run "$dir/run" --out "$dir/figs" 2>"$dir/err"; then fail "figures of a diverged run"; fi
grep -q "unoptimized program's simulation diverged" "$dir/err" || fail "figures: $(cat "$dir/err")"

"$hexgait" sweep --seeds 1-2 --dt 0.012 --population 6 --generations 2 --time 100 --out "$dir/sweep" --quiet >"$dir/table"
grep -q "| 0.00 (diverged) |.*| 0 of 2 | 32 of 32 |$" "$dir/table" || fail "sweep table: $(cat "$dir/table")"
grep -q ",1,1,16$" "$dir/sweep/summary.csv" || fail "sweep summary.csv: $(cat "$dir/sweep/summary.csv")"

"$hexgait" repertoire --dt 0.05 --evaluations 40 --batch 40 --time 100 --no-movie --out "$dir/rep" --quiet >/dev/null
row=$(grep "^| MAP-Elites |" "$dir/rep/table.md")
diverged=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $4); print $4}')
[ "$diverged" -ge 1 ] || fail "repertoire table counts no divergence: $row"
python3 - "$dir/rep" "$diverged" <<'PY' || fail "repertoire.json / progress.csv disagree with table.md"
import csv, json, sys
d, n = sys.argv[1], int(sys.argv[2])
assert json.load(open(d + "/repertoire.json"))["methods"][0]["diverged"] == n
rows = list(csv.DictReader(open(d + "/progress.csv")))
assert int(rows[-1]["diverged"]) == n
PY

"$hexgait" endurance --genome "$(dirname "$0")/../data/evolved_seed1.genome" --random 0 --dt 0.05 \
  --time 100 --long 2 --horizon 2 --trials 2 --out "$dir/end" --quiet >/dev/null
grep -q "diverged (stops standing there; not a fall) |" "$dir/end/table.md" || fail "endurance: no diverged column"
grep "^| genome files | 1 |" "$dir/end/table.md" | grep -q "| 1 |$" || fail "endurance: $(cat "$dir/end/table.md")"
echo "divergence: ok"
