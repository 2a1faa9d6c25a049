#!/usr/bin/env python3
"""Replays every elite of a repertoire's archive.csv at another precision and says how many
still stand the whole test, and how far their distances moved.

Why: a float repertoire is faster, but its elites are stored as genomes and replayed by
'simulate' and the movie in double. This measures how many of them are still the gaits the map
shows (docs/speed.md, "The repertoire's precision").

  usage: scripts/replay_archive.py ARCHIVE_CSV [--precision double|float] [--time T]
  needs: the Python module (build/python on PYTHONPATH, or HEXGAIT_PYTHON_DIR), NumPy
"""
import argparse
import csv
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.environ.get("HEXGAIT_PYTHON_DIR", os.path.join(here, "..", "build", "python")))
try:
    import numpy as np
    import hexgait
except ImportError as e:
    sys.exit(f"replay_archive: {e} (needs NumPy and the hexgait module: build/python, "
             "or HEXGAIT_PYTHON_DIR)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("archive_csv")
    parser.add_argument("--precision", choices=["double", "float"], default="double",
                        help="precision to replay in (default: double, what 'simulate' uses)")
    parser.add_argument("--time", type=float, default=1000.0, help="test length (default 1000)")
    args = parser.parse_args()
    try:
        with open(args.archive_csv, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"replay_archive: {args.archive_csv}: {e.strerror}")
    if not rows or "solution_0" not in rows[0] or "objective" not in rows[0]:
        sys.exit(f"replay_archive: {args.archive_csv}: not a repertoire archive.csv")
    # archive.csv's layout is pyribs' (docs/commands.md): objective, measures_*, solution_*.
    solution = [c for c in rows[0] if c.startswith("solution_")]
    genomes = np.array([[int(r[c]) for c in solution] for r in rows], dtype=np.int64)
    symmetric = genomes.shape[1] == 60
    stored = np.array([float(r["objective"]) for r in rows])
    ev = hexgait.Evaluator(time=args.time, precision=args.precision, symmetric=symmetric)
    out = ev.evaluate(genomes)
    stand = ~(np.asarray(out["fell"]) | np.asarray(out["diverged"]))
    distance = np.asarray(out["distance"])
    change = np.abs(distance[stand] - stored[stand]) / np.maximum(np.abs(stored[stand]), 1e-9)
    print(f"elites: {len(rows)}")
    print(f"still stand in {args.precision}: {stand.sum()} ({100.0 * stand.mean():.1f}%)")
    print(f"fell or diverged in {args.precision}: {(~stand).sum()}")
    if stand.any():
        print(f"distance change of those standing: median {100 * np.median(change):.1f}%, "
              f"90th percentile {100 * np.percentile(change, 90):.1f}%")


if __name__ == "__main__":
    main()
