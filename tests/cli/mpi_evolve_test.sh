#!/usr/bin/env bash
# evolve (the GA and CMA-ES) and repertoire under mpirun give the same bytes as without it; a job whose rank dies stops with the
# last checkpoint intact, and --resume finishes it bit-identically. Skips (77) without MPI.
set -euo pipefail
hexgait="$1"
"$hexgait" --version | grep -q "MPI built in" || { echo "MPI not built in: skipped"; exit 77; }
command -v mpirun >/dev/null || { echo "no mpirun: skipped"; exit 77; }
mpirun=(mpirun --allow-run-as-root --oversubscribe)
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
# 300 time units per evaluation: what is compared is the bytes, not the walk. The sanitizer build
# (HEXGAIT_SANITIZED, set by tests/CMakeLists.txt) runs at a tenth of the speed: 120 there, and
# the killed job 10 generations, not 20: the kill comes 0.5 s after the first checkpoint, with
# about 9 generations to go (the 10 took 9 s in one process there, idle).
time=300
long_generations=20
[ -z "${HEXGAIT_SANITIZED:-}" ] || { time=120; long_generations=10; }
flags=(--seed 5 --population 24 --generations 4 --time $time --quiet)

"$hexgait" evolve "${flags[@]}" --out "$dir/plain"
"${mpirun[@]}" -np 3 "$hexgait" evolve "${flags[@]}" --out "$dir/A" > "$dir/A.log" 2>&1
for f in fitness.csv best.genome; do cmp "$dir/plain/$f" "$dir/A/$f"; done
# Float lanes and the creature kernel across ranks, one thread each.
"$hexgait" evolve "${flags[@]}" --precision float --out "$dir/plainf"
"${mpirun[@]}" -np 2 "$hexgait" evolve "${flags[@]}" --precision float --threads 1 \
  --out "$dir/Bf" > "$dir/Bf.log" 2>&1
for f in fitness.csv best.genome; do cmp "$dir/plainf/$f" "$dir/Bf/$f"; done

# CMA-ES: the search runs on rank 0 only, its candidates on every rank.
cma=(--algorithm cmaes --seed 1 --generations 3 --time $time --quiet)
"$hexgait" evolve "${cma[@]}" --out "$dir/cma1"
"${mpirun[@]}" -np 3 "$hexgait" evolve "${cma[@]}" --threads 1 --out "$dir/cma3" \
  > "$dir/cma3.log" 2>&1 || { cat "$dir/cma3.log"; exit 1; }
for f in fitness.csv best.genome; do cmp "$dir/cma1/$f" "$dir/cma3/$f"; done

# MAP-Elites' batches across ranks: the same archive, in double and in float with admissions
# confirmed in double (on rank 0). (The default, auto, is double under mpirun.)
# CMA-MAE's emitters likewise.
for run in "double" "float" "double --algorithm cma-mae --emitters 5"; do
  set -- $run
  precision=$1
  shift
  name=$(echo "$run" | tr -d ' -')
  rep=(--evaluations 160 --batch 40 --bins 3 --time 100 --seed 2 --precision $precision --no-movie --quiet "$@")
  "$hexgait" repertoire "${rep[@]}" --out "$dir/rep1$name" >/dev/null
  "${mpirun[@]}" -np 3 "$hexgait" repertoire "${rep[@]}" --threads 1 --out "$dir/rep3$name" \
    > "$dir/rep3.log" 2>&1 || { cat "$dir/rep3.log"; exit 1; }
  cmp "$dir/rep1$name/archive.csv" "$dir/rep3$name/archive.csv"
done

# A rank killed mid-run: the job stops with an error and the checkpoint is a complete one.
long=(--seed 5 --population 24 --generations $long_generations --time $time --quiet)
"$hexgait" evolve "${long[@]}" --out "$dir/plain_long"
set +e
# Rank 2 is killed once rank 0 has written its first checkpoint.
KILL_AFTER="$dir/C/checkpoint.json" "${mpirun[@]}" -np 3 bash -c '
  if [ "$OMPI_COMM_WORLD_RANK" = 2 ]; then
    "$0" "$@" & pid=$!
    for _ in $(seq 600); do [ -f "$KILL_AFTER" ] && break; sleep 0.1; done
    sleep 0.5; kill -9 $pid; wait $pid; exit 137
  fi
  exec "$0" "$@"' "$hexgait" evolve "${long[@]}" --out "$dir/C" > "$dir/C.log" 2>&1
code=$?
set -e
[ "$code" -ne 0 ] || { echo "a job with a killed rank exited 0"; cat "$dir/C.log"; exit 1; }
[ -f "$dir/C/checkpoint.json" ] || { echo "no checkpoint after the killed rank"; exit 1; }
python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$dir/C/checkpoint.json"
[ ! -f "$dir/C/fitness.csv" ] || { echo "the run finished before the kill"; exit 1; }
"${mpirun[@]}" -np 2 "$hexgait" evolve --resume "$dir/C" --quiet > "$dir/D.log" 2>&1
for f in fitness.csv best.genome; do cmp "$dir/plain_long/$f" "$dir/C/$f"; done
echo "mpi evolve: byte-identical with 3 and 2 ranks (repertoire with 3); killed rank stops the job; resume matches"
