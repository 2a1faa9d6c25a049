#!/usr/bin/env python3
"""Would the loop do better with its kernel over the genes? (docs/results.md, "A kernel over the
genes"). Intelligent Trial and Error's GP measures how alike two elites are by their descriptors
(the duty factors), and on a damaged creature an elite's distance correlates only weakly with its
nearest neighbour's there. The elites' genes are the other space the map holds: MAP-Elites'
children are a few bit flips from their parents, so elites close in genes are relatives, and may
walk alike on a damaged creature where their descriptors do not say so.

On the maps and tables of scripts/adapt_prior_study.py (every elite's distance on every damaged
creature, cached), this runs the library's loop (hexgait.trial_and_error, its defaults but the
length scale) with the elites placed at their descriptors (what `adapt` does), at their genes,
and at both side by side, on the weak, locked and short damages of every leg (54 runs, the
goals' runs). The genes are scaled so that the median gap to an elite's nearest neighbour is the
descriptors' (about 0.09), which puts the length scales of the two spaces on one footing. Each
run is cut after the stop rule and at a fixed 10 trials (the goal's budget).

    PYTHONPATH=build/python scripts/adapt_kernel_study.py [OUT_DIR]   (default out/adapt_study)
"""
import pathlib
import statistics
import sys

import numpy as np

import hexgait
from adapt_gp_study import DAMAGES, random_best
from adapt_landscape import GOAL_BEATS, GOAL_FRACTION, GOAL_TRIALS, nearest_neighbours
from adapt_prior_study import SEEDS, damaged_tables

LENGTH_SCALES = (0.05, 0.07, 0.1, 0.15, 0.2, 0.3)  # around the library's default (docs/model.md)


def genes_in_table_order(repertoire, descriptors):
    """Each elite's genes, in the row order of the cached tables (matched by their descriptors,
    which are the archive's own numbers, one cell each)."""
    frame = hexgait.load_archive(str(repertoire))
    measures = frame[[f"measures_{i}" for i in range(descriptors.shape[1])]].to_numpy()
    genes = frame[[c for c in frame.columns if c.startswith("solution_")]].to_numpy(float)
    rows = []
    for descriptor in descriptors:
        match = np.flatnonzero((measures == descriptor).all(axis=1))
        if len(match) != 1:
            sys.exit(f"{repertoire}: its cached tables do not match its archive; delete "
                     "prior_tables_*.npz and run again")
        rows.append(match[0])
    return genes[rows]


def main():
    if len(sys.argv) > 2:
        sys.exit("usage: adapt_kernel_study.py [OUT_DIR]")
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/adapt_study")
    cuts = {"after the stop rule": {}, f"at {GOAL_TRIALS} trials": {"stop": None,
                                                                     "trials": GOAL_TRIALS}}
    smoothness = {"descriptors": [], "genes": []}
    results = {}  # (space, length scale, cut) -> [(fraction of the best, trials, beats random)]
    for seed in SEEDS:
        descriptors, intact, tables = damaged_tables(out, seed)
        genes = genes_in_table_order(out / f"repertoire_{seed}", descriptors)
        nearest_d, gap_d = nearest_neighbours(descriptors)
        nearest_g, gap_g = nearest_neighbours(genes)
        scaled = genes * (np.median(gap_d) / np.median(gap_g))
        spaces = {"descriptors": descriptors, "genes": scaled,
                  "both": np.hstack([descriptors, scaled])}
        for name, damaged in tables.items():
            if name.split(":")[1] not in DAMAGES:
                continue
            smoothness["descriptors"].append(np.corrcoef(damaged, damaged[nearest_d])[0, 1])
            smoothness["genes"].append(np.corrcoef(damaged, damaged[nearest_g])[0, 1])
            for space, points in spaces.items():
                for scale in LENGTH_SCALES:
                    for cut, flags in cuts.items():
                        r = hexgait.trial_and_error(points, intact, damaged, length_scale=scale,
                                                    **flags)
                        used = len(r["trials"])
                        adapted = r["trials"][-1]["best"]
                        beats = adapted > random_best(damaged, used, f"{seed}:{name}")
                        results.setdefault((space, scale, cut), []).append(
                            (adapted / damaged.max(), used, beats))
    med = statistics.median
    runs = len(smoothness["genes"])
    print(f"An elite's damaged distance against its nearest neighbour's (Pearson, median over "
          f"{runs} runs): in descriptors {med(smoothness['descriptors']):.2f}, in genes "
          f"{med(smoothness['genes']):.2f}.\n")
    print(f"The loop over each space ({runs} runs; medians as a fraction of the best elite on the "
          "damaged creature):\n")
    print("| space | length scale | after the stop rule: trials (median, max) | adapted | "
          f"beats random | at {GOAL_TRIALS} trials: adapted | beats random |")
    print("|---|---|---|---|---|---|---|")
    stop_cut, fixed_cut = cuts
    for space in ("descriptors", "genes", "both"):
        for scale in LENGTH_SCALES:
            stop, fixed = results[(space, scale, stop_cut)], results[(space, scale, fixed_cut)]
            print(f"| {space} | {scale:g} | {med(r[1] for r in stop):g}, "
                  f"{max(r[1] for r in stop)} | {100 * med(r[0] for r in stop):.0f}% | "
                  f"{sum(r[2] for r in stop)} | {100 * med(r[0] for r in fixed):.0f}% | "
                  f"{sum(r[2] for r in fixed)} |")
    print(f"\nThe goals: {100 * GOAL_FRACTION:.0f}% within {GOAL_TRIALS} trials, beating random "
          f"elites in {GOAL_BEATS} of {runs} runs.")


if __name__ == "__main__":
    main()
