#!/usr/bin/env bash
# The results' bytes pinned: the paper's GA (seeds 1-3, in double and in float lanes), a
# symmetric run, and a 2,000-evaluation repertoire in double and in the default float search
# with double confirmations, each checked against the SHA-256 of its files in
# tests/data/same_bits.sha256. A faster kernel must leave every one unchanged; a change to the
# physics or the search that changes them on purpose rewrites the list (UPDATE=1) and says so
# in its commit.
#   same_bits_test.sh HEXGAIT            check
#   UPDATE=1 same_bits_test.sh HEXGAIT   rewrite tests/data/same_bits.sha256
set -euo pipefail
hexgait=$(realpath "$1")
list="$(cd "$(dirname "$0")/../data" && pwd)/same_bits.sha256"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

for seed in 1 2 3; do
  "$hexgait" evolve --seed "$seed" --out "ga_double_$seed" --quiet
  "$hexgait" evolve --seed "$seed" --precision float --out "ga_float_$seed" --quiet
done
"$hexgait" evolve --seed 1 --symmetric --out ga_symmetric --quiet
for precision in double auto; do
  "$hexgait" repertoire --evaluations 2000 --precision "$precision" --no-movie \
    --out "repertoire_$precision" --quiet > /dev/null
done

sha256sum ga_*/fitness.csv ga_*/best.genome repertoire_*/archive.csv repertoire_*/map.csv \
  | LC_ALL=C sort -k 2 > sums
if [ "${UPDATE:-0}" = 1 ]; then
  cp sums "$list"
  echo "rewrote $list ($(wc -l < sums) files)"
  exit 0
fi
if ! diff "$list" sums; then
  echo "FAIL: results changed bytes (lines above: < pinned, > now)" >&2
  exit 1
fi
echo "$(wc -l < sums) files have their pinned bytes"
