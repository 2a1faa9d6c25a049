#!/usr/bin/env bash
# One run of every command with small settings, as a user would type it: each exits 0 and
# writes the files it names. The quick tier's check that no command is broken; the other
# script tests check what each writes in depth.
#   usage: cli_smoke_test.sh HEXGAIT
set -uo pipefail
hexgait=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
passed=0
failed=0

# smoke "FILES THAT MUST EXIST" ARGS...
smoke() {
  local files=$1
  shift
  if ! "$hexgait" "$@" >"$work/stdout" 2>"$work/stderr"; then
    echo "FAIL: hexgait $* exited non-zero: $(tail -n 2 "$work/stderr")"
    failed=$((failed + 1))
    return
  fi
  for f in $files; do
    if [ ! -s "$f" ]; then
      echo "FAIL: hexgait $* did not write $f"
      failed=$((failed + 1))
      return
    fi
  done
  echo "ok: hexgait $*"
  passed=$((passed + 1))
}

smoke "" --help
smoke "" --version
smoke "" simulate --unoptimized --time 20 --json
smoke "trace.csv" simulate --time 5 --csv trace.csv
smoke "run/fitness.csv run/best.genome run/run.json" evolve --population 2 --generations 2 --time 20 --out run --quiet
smoke "" simulate --genome run/best.genome --time 20
smoke "sweep/summary.csv" sweep --seeds 1-2 --population 2 --generations 1 --time 10 --out sweep --quiet
smoke "endurance/endurance.csv" endurance --run run --random 1 --random-tries 50 --time 20 --long 2 --horizon 2 --trials 1 --out endurance --quiet
smoke "repertoire/archive.csv" repertoire --evaluations 40 --batch 20 --time 20 --showcase 2 --movie-time 4 --out repertoire --quiet
smoke "" inspect
smoke "still.png" still --size 160x120 --out still.png
smoke "strip.png" filmstrip --genome run/best.genome --frames 2 --size 160x120 --out strip.png
smoke "gait.mp4" render --genome run/best.genome --time 10 --size 160x120 --fps 10 --out gait.mp4
smoke "replay.html" replay --run run --time 20 --out replay.html
smoke "movies/unoptimized.mp4 movies/evolved.mp4 movies/comparison.mp4 movies/unoptimized.html movies/evolved.html" movie --run run --time 10 --size 160x120 --fps 10 --out movies
# Implicit Euler's solves and the repertoire workload's 256 children take most of a bench's
# time under the sanitizers (42 of 60 s): cli_bench runs implicit Euler; one run is enough here.
smoke "bench/accuracy.csv" bench accuracy --quick --integrators euler,symplectic-euler,verlet,rk4 --out bench
smoke "bench/stability.csv" bench stability --quick --integrators euler,symplectic-euler,verlet,rk4 --out bench
smoke "" bench speed --seconds 0.02 --repeats 1 --skip-evolve --repertoire-children 16
smoke "" bench early-stop --genomes 4
smoke "" bench movie --time 10 --size 160x120 --repeats 1 --no-ffmpeg --no-memory --out benchmovie
smoke "" bench scale --ranks 1 --population 8 --generations 1 --time 10
smoke "figures/fitness.png" figures --run run --bench bench --time 20 --out figures
smoke "report/index.html" report --run run --movies movies --figures figures --repertoire repertoire --out report

# inspect on a creature of 1,000 particles: its dense whole-creature analyses (hours at that
# size) are skipped with a line saying so; the rest prints in well under a second.
python3 "$(dirname "$0")/../support/make_big_creature.py" "$(dirname "$0")/../../assets/hexapod.json" "$work/big.json"
start=$(date +%s)
if timeout 60 "$hexgait" inspect --creature "$work/big.json" >"$work/stdout" 2>&1 &&
  grep -q "whole-creature analyses .* skipped: 1000 particles" "$work/stdout" &&
  [ $(($(date +%s) - start)) -lt 20 ]; then
  echo "ok: hexgait inspect --creature big.json (1,000 particles)"
  passed=$((passed + 1))
else
  echo "FAIL: inspect of 1,000 particles: $(tail -n 2 "$work/stdout")"
  failed=$((failed + 1))
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
