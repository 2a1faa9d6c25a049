#!/usr/bin/env bash
# sweep: each seed's folder holds what `evolve --seed K` writes (the GA and CMA-ES); a second
# sweep keeps finished seeds; other parameters in the same folder are refused; figures --runs takes the sweep folder;
# under mpirun (when built in) the seeds go to ranks and the files are the same bytes.
set -euo pipefail
hexgait="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
flags=(--population 8 --generations 3 --time 100)

"$hexgait" sweep --seeds 1-2,5 "${flags[@]}" --threads 2 --out "$dir/sw" >"$dir/table" 2>"$dir/log"
for seed in 1 2 5; do
  "$hexgait" evolve --seed "$seed" "${flags[@]}" --threads 1 --out "$dir/ev$seed" --quiet
  for f in fitness.csv best.genome; do  # checkpoint.json and run.json also hold timings
    cmp "$dir/ev$seed/$f" "$dir/sw/seed-$seed/$f" || fail "seed $seed: $f differs from evolve's"
  done
done
[ "$(wc -l <"$dir/sw/summary.csv")" -eq 4 ] || fail "summary.csv should have a header and 3 rows"
grep -q '^| population 8, 3 generations | 1-2,5 | ' "$dir/table" || fail "no table row printed"
cmp "$dir/table" "$dir/sw/table.md" || fail "printed table differs from table.md"

# A second sweep over the same folder runs nothing again and writes the same summary.
cp "$dir/sw/summary.csv" "$dir/summary.first"
touch -d '2000-01-01' "$dir/sw/seed-1/run.json"
"$hexgait" sweep --seeds 1-2,5 "${flags[@]}" --out "$dir/sw" >/dev/null 2>"$dir/log2"
grep -q "3 already done" "$dir/log2" || fail "finished seeds were not kept: $(cat "$dir/log2")"
[ "$(stat -c %Y "$dir/sw/seed-1/run.json")" -lt 1000000000 ] || fail "seed 1 was run again"
cmp "$dir/summary.first" "$dir/sw/summary.csv" || fail "summary changed on the second sweep"

# Other parameters into the same folder: refused, nothing changed.
if "$hexgait" sweep --seeds 1 --population 4 --generations 3 --time 100 --out "$dir/sw" \
  2>"$dir/err"; then
  fail "a sweep of other parameters was accepted into the same folder"
fi
grep -q "holds a run with population 8, not 4" "$dir/err" || fail "wrong message: $(cat "$dir/err")"

# Another motor program (or the same creature path with other content) into the same folder:
# another experiment, refused by the scene fingerprint the seeds' checkpoints record.
sed 's/"cycle_period": *\([0-9.]*\)/"cycle_period": 70/' \
  "$(dirname "$0")/../../assets/metachronal.json" >"$dir/other_motor.json"
cmp -s "$dir/other_motor.json" "$(dirname "$0")/../../assets/metachronal.json" &&
  fail "the test's motor program edit did nothing"
if "$hexgait" sweep --seeds 1-2,5 "${flags[@]}" --motor "$dir/other_motor.json" --out "$dir/sw" \
  2>"$dir/err"; then
  fail "a sweep of another motor program was accepted into the same folder"
fi
grep -q "holds a run of another creature or motor program" "$dir/err" ||
  fail "wrong message: $(cat "$dir/err")"

# A CMA-ES sweep: each seed as `evolve --algorithm cmaes` writes it, continued by a second
# sweep, and refused to a GA sweep.
cma=(--algorithm cmaes --generations 2 --time 50)
"$hexgait" sweep --seeds 1-2 "${cma[@]}" --out "$dir/cma" >/dev/null 2>&1
"$hexgait" evolve --seed 2 "${cma[@]}" --out "$dir/cma-ev2" --quiet
cmp "$dir/cma-ev2/best.genome" "$dir/cma/seed-2/best.genome" || fail "cmaes seed 2 differs from evolve's"
"$hexgait" sweep --seeds 1-2 "${cma[@]}" --out "$dir/cma" >/dev/null 2>"$dir/log3"
grep -q "2 already done" "$dir/log3" || fail "a cmaes sweep was not continued: $(cat "$dir/log3")"
if "$hexgait" sweep --seeds 1 --generations 2 --time 50 --out "$dir/cma" 2>"$dir/err"; then
  fail "a GA sweep was accepted into a cmaes sweep's folder"
fi

# figures --runs takes the sweep folder as its three runs.
"$hexgait" figures --run "$dir/sw/seed-1" --runs "$dir/sw" --time 20 --no-figure1 \
  --out "$dir/figs" >/dev/null
awk -F, 'NR == 2 && $2 != 3 { exit 1 }' "$dir/figs/fitness_seeds.csv" ||
  fail "figures did not read 3 runs from the sweep folder"

if "$hexgait" --version | grep -q "MPI built in" && command -v mpirun >/dev/null; then
  mpirun --allow-run-as-root --oversubscribe -np 3 "$hexgait" sweep --seeds 1-2,5 "${flags[@]}" \
    --out "$dir/mpi" >"$dir/mpi.table" 2>"$dir/mpi.log" || { cat "$dir/mpi.log"; fail "mpirun sweep"; }
  for seed in 1 2 5; do
    for f in fitness.csv best.genome; do
      cmp "$dir/sw/seed-$seed/$f" "$dir/mpi/seed-$seed/$f" || fail "MPI seed $seed: $f differs"
    done
  done
  cmp "$dir/sw/summary.csv" "$dir/mpi/summary.csv" || fail "MPI summary differs"
  echo "sweep: threads, resume, refusal, figures and MPI (3 ranks) ok"
else
  echo "sweep: threads, resume, refusal and figures ok (MPI not built in)"
fi
