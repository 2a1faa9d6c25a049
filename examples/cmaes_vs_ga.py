#!/usr/bin/env python3
"""CMA-ES over the continuous rest-length offsets against the paper's GA, at equal budgets.

All start from the unoptimized program (all offsets zero) and are scored by the same
fitness, the distance walked in --time time units. CMA-ES (Debian's python3-cmaes) proposes
real-valued offsets, bounded to the GA's range [-8, 7] gene steps, and runs them through
hexgait.Evaluator.evaluate_offsets, a whole CMA-ES generation per call. The GA is the paper's
(`hexgait evolve`: population 4, 4-bit genes, roulette wheel, one elite), run for enough
generations to spend the largest budget; its run.json counts the evaluations of each
generation. hexgait's own CMA-ES (`hexgait evolve --algorithm cmaes`, written from Hansen's
tutorial) runs the same task with the same population and initial step, as a check of it
against python3-cmaes. For each method and seed the best distance found within the first B
evaluations is read off one run, for every budget B: the anytime curve of each method.

Writes to --out: results.csv (method, seed, budget, best distance), table.md (median and range
over seeds per method and budget), curve.csv and cmaes_vs_ga.png (best distance against
evaluations: median line, min-max band). Needs the module on PYTHONPATH (build/python) and the
hexgait binary (--hexgait, default build/hexgait).

  PYTHONPATH=build/python python3 examples/cmaes_vs_ga.py             # 10 seeds, 34/340/3400
  PYTHONPATH=build/python python3 examples/cmaes_vs_ga.py --seeds 2 --budgets 12,40 --time 50
"""
import argparse
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

try:
    import cmaes
except ImportError:
    sys.exit("cmaes_vs_ga: needs the cmaes package (Debian: python3-cmaes)")
import hexgait

GENE_MIN, GENE_MAX = -8, 7


def cmaes_curve(evaluator, seed, budget, sigma_steps):
    """Best distance after each of `budget` evaluations of one CMA-ES run."""
    step = evaluator.gene_length_step
    n = evaluator.genes
    bounds = np.tile([GENE_MIN * step, GENE_MAX * step], (n, 1))
    optimizer = cmaes.CMA(mean=np.zeros(n), sigma=sigma_steps * step, bounds=bounds, seed=seed)
    curve, best = [], -math.inf
    while len(curve) < budget:
        xs = np.array([optimizer.ask() for _ in range(optimizer.population_size)])
        distance = evaluator.evaluate_offsets(xs)["distance"]  # 0 for a diverged run
        optimizer.tell([(x, -d) for x, d in zip(xs, distance)])
        for d in distance:
            best = max(best, d)
            curve.append(best)
    return np.array(curve[:budget])


def history_curve(history, budget):
    """Best distance after each evaluation, from a run.json history of whole generations."""
    # A generation's results are known once it is whole: its best counts from its last
    # evaluation on (before the first generation ends there is no result yet: NaN).
    curve, best = [], math.nan
    for generation in history:
        n = generation["evaluations"]
        curve += [best] * (n - 1)
        best = generation["best"] if math.isnan(best) else max(best, generation["best"])
        curve.append(best)
    if len(curve) < budget:
        sys.exit(f"cmaes_vs_ga: a run made {len(curve)} evaluations, fewer than {budget}")
    return np.array(curve[:budget])


def evolve_curve(hexgait_bin, seed, budget, run_time, threads, precision, folder, algorithm,
                 population, extra=()):
    """Best distance after each of `budget` evaluations of one `hexgait evolve` run."""
    elites = 1 if algorithm == "ga" else 0
    generations = max(1, math.ceil((budget - population) / (population - elites)))
    out = pathlib.Path(folder) / f"{algorithm}-seed-{seed}"
    subprocess.run([hexgait_bin, "evolve", "--algorithm", algorithm, "--seed", str(seed),
                    "--population", str(population), "--generations", str(generations),
                    "--time", str(run_time), "--threads", str(threads), "--precision", precision,
                    "--quiet", "--out", str(out), *extra], check=True)
    return history_curve(json.loads((out / "run.json").read_text())["history"], budget)


def write_figure(curves, budgets, out):
    """curve.csv and the gnuplot figure: median and range over seeds against evaluations."""
    largest = max(budgets)
    points = sorted({int(round(x)) for x in np.geomspace(1, largest, 200)} | set(budgets))
    lines = ["evaluations," + ",".join(f"{m}_median,{m}_min,{m}_max" for m in curves)]
    for e in points:
        row = [str(e)]
        for runs in curves.values():
            at = np.array([c[e - 1] for c in runs])
            if np.isnan(at).any():
                row += ["NaN"] * 3
            else:
                row += [f"{np.median(at):.4f}", f"{at.min():.4f}", f"{at.max():.4f}"]
        lines.append(",".join(row))
    (out / "curve.csv").write_text("\n".join(lines) + "\n")
    plot_curve(out, largest, [NAMES[m] for m in curves])


COLOURS = ["#1f4e9c", "#c0501a", "#2a8a3a"]
# How the methods are named in the table and the figure.
NAMES = {"GA": "GA", "CMA-ES": "CMA-ES (python3-cmaes)", "hexgait CMA-ES": "CMA-ES (hexgait)"}


def plot_curve(out, largest, methods):
    """cmaes_vs_ga.png from curve.csv, with gnuplot: a band and a median line per method."""
    bands = [f'"" every ::1 using 1:{3 + 3 * i}:{4 + 3 * i} with filledcurves lc rgb "{c}" '
             f'fs transparent solid 0.2 title "{m} range"'
             for i, (m, c) in enumerate(zip(methods, COLOURS))]
    lines = [f'"" every ::1 using 1:{2 + 3 * i} with lines lw 2.5 lc rgb "{c}" title "{m} median"'
             for i, (m, c) in enumerate(zip(methods, COLOURS))]
    plots = ", \\\n     ".join(bands + lines)
    script = f"""
set terminal pngcairo size 900,560 font "DejaVu Sans,12"
set output "{out / 'cmaes_vs_ga.png'}"
set datafile separator ","
set datafile missing "NaN"
set logscale x
set xrange [1:{largest}]
set key top left
set grid
set xlabel "fitness evaluations"
set ylabel "best distance walked (length units)"
set title "CMA-ES over rest-length offsets and the paper's GA (median and range over seeds)"
plot "{out / 'curve.csv'}" {plots.removeprefix('""')}
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seeds", type=int, default=10, help="seeds 1..N per method (10)")
    parser.add_argument("--budgets", default="34,340,3400", help="evaluation budgets (34,340,3400)")
    parser.add_argument("--time", type=float, default=1000.0, help="simulated time per run (1000)")
    parser.add_argument("--sigma", type=float, default=2.0,
                        help="CMA-ES initial step, in gene steps (2)")
    parser.add_argument("--threads", type=int, default=0, help="threads (0: all)")
    parser.add_argument("--precision", default="float", choices=["double", "float"],
                        help="number type of both methods' runs (float: about 3x faster here)")
    parser.add_argument("--hexgait", default="build/hexgait", help="the hexgait binary")
    parser.add_argument("--out", default="out/cmaes_vs_ga", help="output folder")
    parser.add_argument("--no-hexgait-cmaes", action="store_true",
                        help="leave out `hexgait evolve --algorithm cmaes`")
    args = parser.parse_args()
    budgets = sorted({int(b) for b in args.budgets.split(",")})
    if args.seeds < 1 or budgets[0] < 5:
        sys.exit("cmaes_vs_ga: need at least 1 seed and budgets of at least 5 evaluations")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    evaluator = hexgait.Evaluator(time=args.time, threads=args.threads, precision=args.precision)
    # Hansen's default population for n dimensions, as python3-cmaes and hexgait both take it.
    cmaes_population = 4 + math.floor(3 * math.log(evaluator.genes))
    curves = {"GA": [], "CMA-ES": []}
    if not args.no_hexgait_cmaes:
        curves["hexgait CMA-ES"] = []
    started = time.monotonic()
    with tempfile.TemporaryDirectory() as folder:
        for seed in range(1, args.seeds + 1):
            common = (args.hexgait, seed, budgets[-1], args.time, args.threads, args.precision,
                      folder)
            curves["GA"].append(evolve_curve(*common, "ga", 4))
            curves["CMA-ES"].append(cmaes_curve(evaluator, seed, budgets[-1], args.sigma))
            if "hexgait CMA-ES" in curves:
                curves["hexgait CMA-ES"].append(
                    evolve_curve(*common, "cmaes", cmaes_population, ["--sigma", str(args.sigma)]))
            ends = ", ".join(f"{m} {c[-1][-1]:.2f}" for m, c in curves.items())
            print(f"seed {seed}/{args.seeds}: {ends} ({time.monotonic() - started:.0f} s)",
                  file=sys.stderr)

    rows = ["method,seed,budget,best"]
    table = ["| evaluations | " + " | ".join(f"{NAMES[m]}: median [min, max]" for m in curves) +
             " | CMA-ES ahead |",
             "|---:|" + "---|" * len(curves) + "---:|"]
    for b in budgets:
        cells = []
        for method, runs in curves.items():
            at = np.array([c[b - 1] for c in runs])
            rows += [f"{method},{s + 1},{b},{v:.6f}" for s, v in enumerate(at)]
            cells.append(f"{np.median(at):.2f} [{at.min():.2f}, {at.max():.2f}]")
        wins = sum(c[b - 1] > g[b - 1] for c, g in zip(curves["CMA-ES"], curves["GA"]))
        table.append(f"| {b:,} | " + " | ".join(cells) + f" | {wins} of {args.seeds} seeds |")
    (out / "results.csv").write_text("\n".join(rows) + "\n")
    (out / "table.md").write_text("\n".join(table) + "\n")
    write_figure(curves, budgets, out)
    print("\n".join(table))
    print(f"wrote {out}/results.csv, table.md, curve.csv, cmaes_vs_ga.png", file=sys.stderr)


if __name__ == "__main__":
    main()
