#!/usr/bin/env bash
# MAP-Elites against MAP-Elites with iso+line variation and CMA-MAE on the same budget
# (docs/results.md, "CMA-MAE against MAP-Elites"):
# `hexgait repertoire` with each algorithm's defaults, SEEDS (default "1 2 3"), EVALUATIONS each
# (10,000 unless given), the paper's time of 1000 units, the default precision (float,
# admissions confirmed in double). Extra arguments are CMA-MAE settings for a further row
# ("--learning-rate 1" makes a CMA-ME row). Prints one row per run, then per algorithm the
# median over seeds: filled cells, QD-score (the sum of the elites' distances, and normalised as
# pyribs and QDax report it: divided by the grid's cells), the farthest standing gait, the share
# of the union of every run's cells (a lower bound on the cells this motor program can reach)
# that the algorithm's runs fill, and the wall time, with the machine's CPU. With FIGURE=PATH,
# also draws the QD-score against evaluations (median and range over the seeds) with gnuplot.
# UNION_ALSO (study folders made with RUNS, space-separated) adds their finished runs to a second,
# wider union: the tightest bound on the reachable cells that every budget's runs give.
# ALGORITHMS (a space-separated list) runs only those. With RUNS=DIR the runs are kept there and
# a run already finished in it is not run again, and one interrupted (Ctrl-C, a lost session)
# resumes from its last checkpoint (a long study resumes, or gains seeds).
#   scripts/qd_side_by_side.sh [EVALUATIONS [CMA-MAE FLAGS...]] > table.md
set -euo pipefail
cd "$(dirname "$0")/.."
evaluations=${1:-10000}
shift $(($# > 0 ? 1 : 0))
hexgait=$(realpath "${HEXGAIT:-build/hexgait}")
if [ -n "${RUNS:-}" ]; then
  work=$(realpath -m "$RUNS")
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
read -r -a seeds <<< "${SEEDS:-1 2 3}"
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
echo
echo "| algorithm | seed | cells | QD-score | farthest | wall s |"
echo "|---|---|---|---|---|---|"
read -r -a runs <<< "${ALGORITHMS:-map-elites iso-line cma-mae}"
[ $# -eq 0 ] || runs+=("cma-mae $*")
for run in "${runs[@]}"; do
  for seed in "${seeds[@]}"; do
    out="$work/runs/$(echo "$run" | tr -c 'a-z0-9' '_')/$seed"
    mkdir -p "$(dirname "$out")"
    if [ ! -f "$out/name" ]; then
      if [ -f "$out/archive.json" ] && [ ! -f "$out/repertoire.json" ]; then
        args=(--resume "$out")  # an interrupted run: its archive holds its settings
      else
        # shellcheck disable=SC2206 # the run's words are its flags
        args=(--algorithm $run --seed "$seed" --evaluations "$evaluations" --out "$out")
      fi
      # The budget is this script's argument, so a run past an hour is what was asked for.
      "$hexgait" repertoire "${args[@]}" --allow-long --no-movie --quiet >/dev/null
      echo "$run" > "$out/name"
    fi
    python3 - "$out/repertoire.json" "$run" "$seed" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
m = r["methods"][0]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {m['filled']} | {m['qd_score']:.1f} | "
      f"{m['best_standing']:.3f} | {m['seconds']:.0f} |")
PY
  done
done
echo
echo "Medians over the seeds (QD-score normalised: divided by the grid's cells; union: the cells"
echo "any run filled, each algorithm's runs' share of it):"
echo
python3 - "$work/runs" "${FIGURE:-}" "${UNION_ALSO:-}" <<'PY'
import csv, json, pathlib, statistics, subprocess, sys
root, figure, also = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3].split()
def filled_cells(out):
    with open(out / "archive.csv") as f:
        return {int(row["index"]) for row in csv.DictReader(f)}
runs = {}
for out in sorted(root.glob("*/*")):
    if not (out / "name").is_file():
        continue  # a run under way in another process, or interrupted: not finished
    record = json.loads((out / "repertoire.json").read_text())
    cells = filled_cells(out)
    with open(out / "progress.csv") as f:
        progress = [(int(r["evaluations"]), float(r["qd_score"])) for r in csv.DictReader(f)
                    if r["method"] == "0"]
    history = json.loads((out / "archive.json").read_text())["history"]
    runs.setdefault((out / "name").read_text().strip(), []).append(
        {"record": record, "cells": cells, "progress": progress, "history": history,
         "seed": record["seed"]})
union = set().union(*(r["cells"] for rs in runs.values() for r in rs))
grid = next(iter(runs.values()))[0]["record"]["cells"]
print(f"{len(union)} cells in the union of every run, of {grid}\n")
if also:
    # Other studies' runs (other budgets) tighten the bound on the reachable cells.
    for study in also:
        if not pathlib.Path(study, "runs").is_dir():
            sys.exit(f"scripts/qd_side_by_side.sh: UNION_ALSO: {study} holds no runs/ folder")
    others = [out for study in also for out in sorted(pathlib.Path(study, "runs").glob("*/*"))
              if (out / "name").is_file()]
    for out in others:
        if json.loads((out / "repertoire.json").read_text())["cells"] != grid:
            sys.exit(f"scripts/qd_side_by_side.sh: {out} was run on another grid")
    wider = union.union(*(filled_cells(out) for out in others))
    print(f"{len(wider)} cells ({100 * len(wider) / grid:.1f}% of the grid) in the union of these "
          f"runs and the {len(others)} finished runs of {' '.join(also)}\n")
print("| algorithm | runs | cells | QD-score | normalised QD-score | farthest | union covered | wall s |")
print("|---|---|---|---|---|---|---|---|")
for name, rs in runs.items():
    m = [r["record"]["methods"][0] for r in rs]
    med = lambda values: statistics.median(values)
    covered = len(set().union(*(r["cells"] for r in rs)))
    print(f"| {name} | {len(rs)} | {med([x['filled'] for x in m]):.0f} | "
          f"{med([x['qd_score'] for x in m]):.1f} | {med([x['qd_score'] / grid for x in m]):.4f} | "
          f"{med([x['best_standing'] for x in m]):.3f} | {100 * covered / len(union):.0f}% | "
          f"{med([x['seconds'] for x in m]):.0f} |")
# Each batch's own seconds (archive.json's history), so a stretch is timed even when a run was
# interrupted and resumed, or shared the machine for a while.
print("\nMedian seconds a batch, by tenth of the budget (each batch's own time):\n")
print("| algorithm | seed | " + " | ".join(f"{10 * t}-{10 * t + 10}%" for t in range(10)) + " |")
print("|---|---|" + "---|" * 10)
for name, rs in runs.items():
    for r in rs:
        budget = r["record"]["methods"][0]["evaluations"]
        tenths = [[b["seconds"] for b in r["history"]
                   if t * budget < 10 * b["evaluations"] <= (t + 1) * budget] for t in range(10)]
        print(f"| {name} | {r['seed']} | " +
              " | ".join(f"{statistics.median(x):.2f}" if x else "" for x in tenths) + " |")
# The last half alone: a long run's steady rate, past a start that may have shared the machine.
print("\nThe last half of each run (its batches' own seconds summed):\n")
print("| algorithm | seed | seconds | evaluations a second | QD-score gained | "
      "QD-score gained a second | children confirmed in double |")
print("|---|---|---|---|---|---|---|")
for name, rs in runs.items():
    for r in rs:
        budget = r["record"]["methods"][0]["evaluations"]
        half = [b for b in r["history"] if 2 * b["evaluations"] > budget]
        start = [b for b in r["history"] if 2 * b["evaluations"] <= budget]
        if not half or not start:
            continue
        seconds = sum(b["seconds"] for b in half)
        gained = half[-1]["qd_score"] - start[-1]["qd_score"]
        print(f"| {name} | {r['seed']} | {seconds:.0f} | "
              f"{(half[-1]['evaluations'] - start[-1]['evaluations']) / seconds:.0f} | "
              f"{gained:.0f} | {gained / seconds:.1f} | "
              f"{half[-1]['confirmed'] - start[-1]['confirmed']} |")
if figure:
    data = pathlib.Path(figure).with_suffix(".dat")
    with open(data, "w") as f:
        for name, rs in runs.items():
            f.write(f'# {name}\n')  # a comment: gnuplot reads no text from it
            for k, (evaluations, _) in enumerate(rs[0]["progress"]):
                scores = [r["progress"][k][1] for r in rs if k < len(r["progress"])]
                f.write(f"{evaluations} {statistics.median(scores)} {min(scores)} {max(scores)}\n")
            f.write("\n\n")
    # gnuplot's single-quoted strings escape a quote by doubling it.
    quote = lambda text: "'" + str(text).replace("'", "''") + "'"
    seeds_of = lambda count: f"{count} seed{'s' if count != 1 else ''}"
    runs_of = lambda rs: f"seed {rs[0]['seed']}" if len(rs) == 1 else seeds_of(len(rs))
    # CMA-MAE with a learning rate of 1 is CMA-ME (Fontaine et al. 2020): the name readers know.
    label = lambda name: "CMA-ME (" + name + ")" if name == "cma-mae --learning-rate 1" else name
    plots = ", ".join(
        f"{quote(data)} index {i} using 1:3:4 with filledcurves fs transparent solid 0.2 notitle lc {i + 1}, "
        f"'' index {i} using 1:2 with lines lw 2 lc {i + 1} title {quote(f'{label(name)} ({runs_of(rs)})')}"
        for i, (name, rs) in enumerate(runs.items()))
    counts = sorted({len(rs) for rs in runs.values()})
    if counts == [1]:  # one run each: no median or range to speak of
        title = "QD-score against evaluations: one run each"
    else:
        seeds = seeds_of(counts[0]) if len(counts) == 1 else f"{counts[0]}-{counts[-1]} seeds"
        title = f"QD-score against evaluations: median and range over {seeds}"
    subprocess.run(["gnuplot"], check=True, text=True, input=(
        f"set terminal pngcairo size 1000,600 font ',11'\nset output {quote(figure)}\n"
        "set xlabel 'evaluations'\nset ylabel 'QD-score (sum of the distances of the elites)'\n"
        f"set key left top\nset grid\nset title {quote(title)}\nplot {plots}\n"))
    print(f"\nfigure: {figure} (data: {data})")
PY
