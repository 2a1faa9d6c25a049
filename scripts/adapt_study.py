#!/usr/bin/env python3
"""Summarises scripts/adapt_study.sh's adapt folders: per length scale and kind of damage, the
median trials to stop and the adapted distance as a fraction of the best elite's on the damaged
creature, against keeping the intact best gait, the best of as many random elites, and the
paper's GA started from the intact best. Writes OUT/summary.csv and prints a Markdown table.

    scripts/adapt_study.py OUT_DIR
"""
import collections
import csv
import itertools
import json
import math
import pathlib
import statistics
import sys


def main():
    out = pathlib.Path(sys.argv[1])
    rows, refused = [], []
    for path in sorted(out.glob("adapt_*")):
        if (path / "refused.txt").exists():
            refused.append((path.name, (path / "refused.txt").read_text().strip()))
            continue
        j = json.loads((path / "adapt.json").read_text())
        best = j["best_elite_on_damaged"]["distance"]
        kind = j["damage"].split(":")[1].split("=")[0]
        rows.append({
            "folder": path.name, "damage": j["damage"], "kind": kind,
            "length_scale": j["params"]["length_scale"], "trials": j["trials"],
            "best_elite": best, "adapted": j["adapted"]["distance"],
            "intact": j["intact_best"]["damaged_distance"],
            "random": j["random_elites"]["best"], "ga": j["ga_from_intact_best"]["best"],
            "ga_evaluations": j["ga_from_intact_best"]["evaluations"],
        })
    keys = list(rows[0].keys())
    with open(out / "summary.csv", "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(str(r[k]) for k in keys) + "\n")

    def fraction(r, key):
        return r[key] / r["best_elite"] if r["best_elite"] > 0 else float("nan")

    groups = collections.defaultdict(list)
    for r in rows:
        groups[(r["length_scale"], r["kind"])].append(r)
        groups[(r["length_scale"], "all")].append(r)
    print("| length scale | damage | runs | trials (median, max) | adapted | intact best gait | "
          "random elites | GA from the intact best (evaluations) | adapted beats intact / random / GA |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (scale, kind), g in sorted(groups.items(), key=lambda kv: (-kv[0][0], kv[0][1] == "all", kv[0][1])):
        med = lambda key: statistics.median(fraction(r, key) for r in g)  # noqa: E731
        wins = lambda key: sum(r["adapted"] > r[key] for r in g)  # noqa: E731
        print("| %.1f | %s | %d | %g, %d | %.0f%% | %.0f%% | %.0f%% | %.0f%% (%g) | %d / %d / %d |" % (
            scale, kind, len(g), statistics.median(r["trials"] for r in g),
            max(r["trials"] for r in g), 100 * med("adapted"), 100 * med("intact"),
            100 * med("random"), 100 * med("ga"),
            statistics.median(r["ga_evaluations"] for r in g), wins("intact"), wins("random"),
            wins("ga")))
    print("\nfractions are medians of each distance over the best elite's on the damaged "
          "creature (found by running every elite); %d runs, %d refused" % (len(rows), len(refused)))
    # How close the elites lie: the median distance between two elites' descriptors, per seed.
    for elites in sorted(out.glob("adapt_*_right_front_locked_l0.4/elites.csv")):
        rows_e = list(csv.DictReader(open(elites)))
        dims = sum(1 for k in rows_e[0] if k.startswith("descriptor_"))
        points = [[float(r["descriptor_%d" % k]) for k in range(dims)] for r in rows_e]
        print("%s: %d elites, median distance between two descriptors %.2f" % (
            elites.parent.name.split("_right")[0], len(points),
            statistics.median(math.dist(a, b) for a, b in itertools.combinations(points, 2))))
    for name, why in refused:
        print("refused: %s: %s" % (name, why.splitlines()[-1]))


if __name__ == "__main__":
    main()
