#!/usr/bin/env python3
"""How much of the test each method's children run (docs/results.md, "What a child costs"): a
child that falls ends its run there (the repertoire's runs end at a fall) and its lanes take
the next child, so a method whose children stand more simulates more per evaluation.

Runs each archive method's search through hexgait.Search with the settings `hexgait repertoire`
uses by default (float, admissions confirmed in double, the run ending at a fall, the paper's
1000 time units), so its children are the command's, and counts per tenth of the run: the share
of children that fell, and the simulated time per child as a share of the whole test. The
confirmations' double runs are not counted (the command's progress gives those).

    PYTHONPATH=build/python scripts/qd_fall_share.py [EVALUATIONS [SEED]]   (default 20000, 1)

About 9 minutes for the four methods at 20,000 on the 2-core machine, 47 at 100,000. Prints a
Markdown table.
"""
import sys

import numpy as np

import hexgait

METHODS = [  # (label, algorithm, settings): the four of docs/results.md's comparison
    ("MAP-Elites", "map-elites", {}),
    ("iso+line", "iso-line", {}),
    ("CMA-MAE", "cma-mae", {}),
    ("CMA-ME (cma-mae, learning rate 1)", "cma-mae", {"learning_rate": 1.0}),
]
TENTHS = 10


def measure(algorithm, settings, evaluations, seed):
    """Per child asked: whether it fell, and how long it ran (the fall's time, or the whole)."""
    evaluator = hexgait.Evaluator(precision="float", stop_at_fall=True)  # the paper's test
    search = hexgait.Search(algorithm, evaluator, seed=seed, evaluations=evaluations,
                            confirm_in_double=True, **settings)
    fell, ran = [], []
    while not search.done:
        results = evaluator.evaluate_offsets(search.ask())
        fell.append(np.asarray(results["fell"], dtype=bool))
        ran.append(np.asarray(results["end_time"]))
        search.tell(results)
    last = search.history()[-1]  # the command's table gives the same for the same seed
    return np.concatenate(fell), np.concatenate(ran) / evaluator.time, last["filled"], last["qd_score"]


def main():
    try:
        evaluations = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
        seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
        if len(sys.argv) > 3 or evaluations < 1 or seed < 0:
            raise ValueError
    except ValueError:
        sys.exit("usage: scripts/qd_fall_share.py [EVALUATIONS (>= 1) [SEED (>= 0)]]")
    print(f"{evaluations} evaluations, seed {seed}; per child: the share that fell, and the "
          "simulated time as a share of the whole test (the whole run, then its first and last "
          "tenth)\n")
    print("| method | cells | QD-score | fell | test run | fell, first tenth | test run, first "
          "tenth | fell, last tenth | test run, last tenth |")
    print("|---|---|---|---|---|---|---|---|---|")
    for label, algorithm, settings in METHODS:
        fell, ran, cells, qd_score = measure(algorithm, settings, evaluations, seed)
        first, last = slice(0, len(fell) // TENTHS), slice(len(fell) - len(fell) // TENTHS, None)
        print(f"| {label} | {cells} | {qd_score:.1f} | "
              f"{100 * fell.mean():.0f}% | {100 * ran.mean():.0f}% | "
              f"{100 * fell[first].mean():.0f}% | {100 * ran[first].mean():.0f}% | "
              f"{100 * fell[last].mean():.0f}% | {100 * ran[last].mean():.0f}% |", flush=True)


if __name__ == "__main__":
    main()
