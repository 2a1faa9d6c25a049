#!/usr/bin/env bash
# Bad input on the command line: each case must exit non-zero, print exactly one line on
# stderr that contains the expected words, and leave no output file behind.
set -u
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
cases=0

# expect_error "expected text" ARGS...   (run from $work; checks no new files appear in $work/out)
expect_error() {
  local expected=$1
  shift
  cases=$((cases + 1))
  mkdir -p "$work/out"
  local before after
  before=$(find "$work/out" | sort)
  "$hexgait" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  after=$(find "$work/out" | sort)
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ "$code" -eq 0 ]; then
    echo "FAIL: exit 0 for: $*"; failures=$((failures + 1))
  elif [ "$lines" -ne 1 ]; then
    echo "FAIL: $lines stderr lines for: $*"; cat "$work/stderr"; failures=$((failures + 1))
  elif ! grep -qF -- "$expected" "$work/stderr"; then
    echo "FAIL: expected '$expected' for: $*"; cat "$work/stderr"; failures=$((failures + 1))
  elif [ "$before" != "$after" ]; then
    echo "FAIL: files left behind for: $*"; echo "$after"; failures=$((failures + 1))
  fi
}

# Input files made from the built-in creature.
"$hexgait" simulate --time 1 --json >/dev/null || { echo "FAIL: hexgait does not run"; exit 1; }
asset_dir=$(dirname "$0")/../../assets
[ -f "$asset_dir/hexapod.json" ] || asset_dir=$(dirname "$0")/../assets
edit_json() {  # edit_json OUT PYTHON-EXPRESSION-ON-d
  python3 - "$asset_dir/hexapod.json" "$1" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[3])
open(sys.argv[2], "w").write(json.dumps(d))
PY
}
edit_json "$work/p99.json" 'd["springs"][5]["ends"][1] = 99'
edit_json "$work/negmass.json" 'd["particles"][3]["mass"] = -2.0'
edit_json "$work/missing.json" 'del d["springs"][0]["stiffness"]'
python3 -c "import sys; t=open(sys.argv[1]).read(); open(sys.argv[2],'w').write(t.replace('\"mass\": 1.0', '\"mass\": NaN', 1))" \
  "$asset_dir/hexapod.json" "$work/nan.json"
: >"$work/empty.json"
"$hexgait" evolve --generations 1 --time 5 --out "$work/run" --quiet
head -n -1 "$work/run/best.genome" >"$work/short.genome"
sed '$ s/ [-0-9]*$/ 9/' "$work/run/best.genome" >"$work/range.genome"

cd "$work" || exit 1
expect_error "--time must be a positive" simulate --time 0
expect_error "--time must be a positive" simulate --time -5
expect_error "--dt must be a positive" simulate --dt 0
expect_error "--dt must be a positive" evolve --dt -0.001 --out out/e
expect_error "Could not convert: --time = abc" simulate --time abc
expect_error "not expected" simulate --bogus
expect_error "unknown integrator 'rk9'" simulate --integrator rk9
expect_error "excludes" simulate --unoptimized --genome "$work/run/best.genome"
expect_error "--population must be at least 2" evolve --population 1 --out out/e
expect_error "--generations must be at least 1" evolve --generations 0 --out out/e
expect_error "--threads must be in" evolve --threads -1 --out out/e
expect_error "--batch-lanes must be in" evolve --batch-lanes 17 --out out/e
expect_error "--seconds must be in" bench speed --seconds 0
expect_error "--repeats must be in" bench speed --repeats 0
expect_error "--genomes must be in" bench early-stop --genomes 0
expect_error "A subcommand is required" bench
expect_error "particle index 99 out of range" simulate --creature "$work/p99.json"
expect_error "must be positive" simulate --creature "$work/negmass.json"
expect_error "missing field 'stiffness'" simulate --creature "$work/missing.json"
expect_error "malformed JSON at line" simulate --creature "$work/nan.json"
expect_error "file is empty" simulate --creature "$work/empty.json"
expect_error "is a directory" simulate --creature "$work"
expect_error "no such file" simulate --creature "$work/nope.json"
expect_error "has 119 genes" simulate --genome "$work/short.genome"
expect_error "outside [-8, 7]" simulate --genome "$work/range.genome"
expect_error "does not exist" simulate --csv "$work/no/such/dir/trace.csv"
expect_error "no such file" evolve --motor "$work/nope.json" --out out/e
expect_error "expected WIDTHxHEIGHT" still --size big --out out/s.png
expect_error "must be between 16 and 7680" still --size 8x8 --out out/s.png
expect_error "does not exist" still --out "$work/no/such/dir/s.png"
expect_error "--time must be between" still --time -1 --out out/s.png
expect_error "needs even width and height" render --size 641x360 --time 5 --out out/m.mp4
expect_error "--fps must be between 1 and 240" render --fps 0 --time 5 --out out/m.mp4
expect_error "does not exist" render --time 5 --out "$work/no/such/dir/m.mp4"

echo "$((cases - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
