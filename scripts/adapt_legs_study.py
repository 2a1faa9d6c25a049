#!/usr/bin/env python3
"""Summarises scripts/adapt_legs_study.sh's adapt folders: per method of map and kind of damage,
adaptation after the stop rule and after a fixed 17 trials, as a fraction of the best elite's
distance on the damaged creature (found by running every elite), against keeping the intact best
gait, the best of as many random elites and the paper's GA started from the intact best. Writes
OUT/summary.csv and prints Markdown tables, then what the landscape the loop searches is like
(scripts/adapt_landscape.py).

    scripts/adapt_legs_study.py OUT_DIR [OTHER_DIR]

With OTHER_DIR (another study's folder, e.g. on maps of another budget), also compares the two
in distance walked, run by run: the runs with the same method, seed, leg and damage in both.
"""
import collections
import json
import pathlib
import statistics
import sys

import numpy as np

from adapt_landscape import print_landscape

KINDS = ["weak", "locked", "short", "lost"]


def load(out):
    rows, refused = [], []
    for path in sorted(out.glob("adapt_*")):
        if ".partial" in path.name:  # a run under way (written whole or not at all)
            continue
        if (path / "refused.txt").exists():
            refused.append((path.name, (path / "refused.txt").read_text().strip()))
            continue
        j = json.loads((path / "adapt.json").read_text())
        method = path.name.split("_")[1]
        best = j["best_elite_on_damaged"]["distance"]
        kind = j["damage"].split(":")[1].split("=")[0]
        fixed = {"trials": j["trials"], "adapted": j["adapted"]["distance"],
                 "random": j["random_elites"]["best"], "ga": j["ga_from_intact_best"]["best"]}
        rule = j["at_stop_rule"]
        # The rule never held within the trials run: a run with it would have gone on; it is
        # counted at the last trial run.
        stopped = dict(fixed, held=False) if rule is None else {
            "trials": rule["trials"], "adapted": rule["adapted"],
            "random": rule["random_elites_best"], "ga": rule["ga_from_intact_best"], "held": True}
        rows.append({"folder": path.name, "method": method, "damage": j["damage"], "kind": kind,
                     "best_elite": best, "intact": j["intact_best"]["damaged_distance"],
                     "fixed": fixed, "stopped": stopped})
    return rows, refused


def elite_distances(folder):
    """(descriptors, intact, damaged distances) of every elite, from an adapt folder's elites.csv."""
    data = np.genfromtxt(folder / "elites.csv", delimiter=",", names=True)
    descriptors = np.column_stack([data[n] for n in data.dtype.names if n.startswith("descriptor")])
    return descriptors, data["intact_distance"], data["damaged_distance"]


def table(rows, cut, title):
    print(f"\n{title}\n")
    print("| map | damage | runs | trials (median, max) | adapted | intact best gait | "
          "random elites | GA from the intact best | adapted beats intact / random / GA |")
    print("|---|---|---|---|---|---|---|---|---|")
    groups = collections.defaultdict(list)
    for r in rows:
        groups[(r["method"], r["kind"])].append(r)
        groups[(r["method"], "all")].append(r)
        if r["kind"] != "lost":
            groups[(r["method"], "weak, locked, short")].append(r)
    order = KINDS + ["weak, locked, short", "all"]
    for (method, kind), g in sorted(groups.items(), key=lambda kv: (kv[0][0], order.index(kv[0][1]))):
        def med(key):
            return statistics.median(
                (r[cut][key] if key != "intact" else r["intact"]) / r["best_elite"]
                if r["best_elite"] > 0 else float("nan") for r in g)

        def wins(key):
            return sum(r[cut]["adapted"] > (r[cut][key] if key != "intact" else r["intact"])
                       for r in g)
        trials = [r[cut]["trials"] for r in g]
        print("| %s | %s | %d | %g, %d | %.0f%% | %.0f%% | %.0f%% | %.0f%% | %d / %d / %d |" % (
            method, kind, len(g), statistics.median(trials), max(trials), 100 * med("adapted"),
            100 * med("intact"), 100 * med("random"), 100 * med("ga"), wins("intact"),
            wins("random"), wins("ga")))


def distances(rows):
    """Per kind of map, medians in distance walked after the stop rule, and how often it held."""
    print("\nIn distance walked, after the stop rule (medians):\n")
    print("| map | runs | the best elite on the damaged creature | adapted | as many random elites "
          "| adapted beats random elites | the stop rule held within 17 trials |")
    print("|---|---|---|---|---|---|---|")
    for method in sorted({r["method"] for r in rows}):
        g = [r for r in rows if r["method"] == method]
        print("| %s | %d | %.2f | %.2f | %.2f | %d | %d |" % (
            method, len(g), statistics.median(r["best_elite"] for r in g),
            statistics.median(r["stopped"]["adapted"] for r in g),
            statistics.median(r["stopped"]["random"] for r in g),
            sum(r["stopped"]["adapted"] > r["stopped"]["random"] for r in g),
            sum(r["stopped"]["held"] for r in g)))


def compare(rows, other_rows, out, other):
    """Medians of what each study's runs walk, in distance, over the runs both made."""
    def key(r):
        return r["folder"].removeprefix("adapt_")  # method_seed_leg_kind
    theirs = {key(r): r for r in other_rows}
    matched = [(r, theirs[key(r)]) for r in rows if key(r) in theirs]
    if not matched:
        print(f"\nno run of {out} is also in {other}")
        return
    for method in sorted({r["method"] for r, _ in matched}):  # one kind of map at a time
        compare_method(method, [(r, o) for r, o in matched if r["method"] == method], out, other)


def compare_method(method, pairs, out, other):
    print(f"\nIn distance walked, the {len(pairs)} runs on {method} maps in both {other} and {out} "
          f"(medians):\n")
    print(f"| cut | what | {other} | {out} | {out} farther |")
    print("|---|---|---|---|---|")
    for cut, label in (("stopped", "after the stop rule"), ("fixed", "after 17 trials")):
        for what in ("adapted", "random", "ga"):
            mine = [r[cut][what] for r, _ in pairs]
            them = [o[cut][what] for _, o in pairs]
            print(f"| {label} | {what} | {statistics.median(them):.2f} | "
                  f"{statistics.median(mine):.2f} | {sum(m > t for m, t in zip(mine, them))} |")
    mine = [r["best_elite"] for r, _ in pairs]
    them = [o["best_elite"] for _, o in pairs]
    print(f"| | best elite | {statistics.median(them):.2f} | {statistics.median(mine):.2f} | "
          f"{sum(m > t for m, t in zip(mine, them))} |")


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: scripts/adapt_legs_study.py OUT_DIR [OTHER_DIR]")
    out = pathlib.Path(sys.argv[1])
    rows, refused = load(out)
    if not rows:
        sys.exit(f"no adapt folders in {out}")
    with open(out / "summary.csv", "w") as f:
        f.write("folder,method,damage,best_elite,intact,cut,trials,adapted,random,ga\n")
        for r in rows:
            for cut in ("stopped", "fixed"):
                c = r[cut]
                f.write(f"{r['folder']},{r['method']},{r['damage']},{r['best_elite']},"
                        f"{r['intact']},{cut},{c['trials']},{c['adapted']},{c['random']},"
                        f"{c['ga']}\n")
    table(rows, "stopped", "After the stop rule (the best trial at 90% of the best prediction):")
    table(rows, "fixed", "After a fixed 17 trials:")
    never = sum(not r["stopped"]["held"] for r in rows)
    print(f"\nfractions are medians of each distance over the best elite's on the damaged "
          f"creature (found by running every elite); {len(rows)} runs, {len(refused)} refused; "
          f"in {never} runs the stop rule never held within 17 trials (counted at 17)")
    distances(rows)
    for method in sorted({r["method"] for r in rows}):
        folders = [out / r["folder"] for r in rows if r["method"] == method]
        folders = [f for f in folders if (f / "elites.csv").exists()]  # older adapts had none
        if folders:
            print(f"\n{method} maps:", end="")
            print_landscape([elite_distances(f) for f in folders])
    for record in sorted(out.glob("*_*/repertoire.json")):
        m = json.loads(record.read_text())["methods"][0]
        print(f"map {record.parent.name}: {m['filled']} elites, QD-score {m['qd_score']:.1f}, "
              f"farthest {m['best_standing']:.2f}, {m['evaluations']} evaluations")
    for name, why in refused:
        print("refused: %s: %s" % (name, why.splitlines()[-1]))
    if len(sys.argv) > 2:
        other = pathlib.Path(sys.argv[2])
        compare(rows, load(other)[0], out, other)


if __name__ == "__main__":
    main()
