#!/usr/bin/env bash
# endurance: a sweep's gaits and random ones through every perturbation; the files it promises,
# one row per run, the printed tables equal table.md, and the same bytes on 1 and 2 threads.
set -euo pipefail
hexgait="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$hexgait" sweep --seeds 1-2 --population 4 --generations 1 --time 60 --out "$dir/sw" >/dev/null 2>&1
flags=(--runs "$dir/sw" --random 2 --random-tries 640 --time 60 --long 3 --horizon 2 --trials 2)
"$hexgait" endurance "${flags[@]}" --threads 2 --out "$dir/e2" >"$dir/printed" 2>"$dir/log"
for f in endurance.csv survival.csv survival.gp survival.png survival.svg table.md endurance.json \
  random-1.genome random-2.genome; do
  [ -s "$dir/e2/$f" ] || fail "$f missing or empty"
done
# 4 gaits x (none, push x2, slope up, slope down, jitter x2, symplectic Euler, half step).
rows=$(($(wc -l <"$dir/e2/endurance.csv") - 1))
[ "$rows" -eq 36 ] || fail "endurance.csv has $rows runs, expected 36"
grep -q '^| population 4, 1 generations | 2 | ' "$dir/e2/table.md" || fail "no row for the sweep"
grep -q '^| random genomes that stood the test | 2 | ' "$dir/e2/table.md" ||
  fail "no row for the random genomes"
grep -qF "$(head -n 1 "$dir/e2/table.md")" "$dir/printed" || fail "table not printed"
# The random genomes stand the test: simulate agrees.
"$hexgait" simulate --genome "$dir/e2/random-1.genome" --time 60 --json | grep -q '"fell": false' ||
  fail "random-1.genome falls in the test"

"$hexgait" endurance "${flags[@]}" --threads 1 --out "$dir/e1" --quiet >/dev/null
for f in endurance.csv survival.csv table.md random-1.genome; do
  cmp "$dir/e1/$f" "$dir/e2/$f" || fail "$f differs between 1 and 2 threads"
done
# A second run replaces the folder whole; an input folder is never the output.
"$hexgait" endurance "${flags[@]}" --out "$dir/e1" --quiet >/dev/null
if "$hexgait" endurance "${flags[@]}" --out "$dir/sw" 2>/dev/null; then
  fail "the sweep folder was accepted as output"
fi
[ -f "$dir/sw/seed-1/best.genome" ] || fail "the sweep folder was touched"
echo "endurance: ok"
