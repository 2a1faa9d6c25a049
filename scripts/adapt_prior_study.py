#!/usr/bin/env python3
"""Would a better prior let Intelligent Trial and Error meet its goals? (docs/results.md, "Priors
from other damages"). The loop's prior is each elite's intact distance, which correlates weakly
with its damaged one. A robot could instead simulate a library of damages before it is sent out
and start from the distances its elites walk on those (adaptive prior selection: Kaushik,
Desreumaux and Mouret, "Adaptive prior selection for repertoire-based online adaptation in
robotics", Frontiers in Robotics and AI 6:151, 2020). This script measures whether any prior
made from the other damages could help here, on the repertoires of scripts/adapt_study.sh.

For each map, every elite is run once on every leg with each of four damages (hexgait.adapt,
24 damaged creatures: weak=0.2, locked, short=0.8, lost). For each of those 72 damaged creatures
(the "answer"), the library holds the other 23; the library's loop (hexgait.trial_and_error,
its defaults) then runs with four priors:
  intact          each elite's intact distance (the loop's own prior, what `adapt` does);
  library mean    the mean of the 23 others' distances, elite by elite;
  best of library the one of the 23 most like the answer (the best correlation), chosen
                  knowing the answer: the member a selection rule is after;
  the answer      the damaged distances themselves: a bound on the loop.
Each run is cut twice: after the stop rule, and at a fixed 10 trials (the goal's budget). And
the correlations between the tables say why: how alike two damages' distances are.

    PYTHONPATH=build/python scripts/adapt_prior_study.py [OUT_DIR]   (default out/adapt_study)

Needs OUT_DIR/repertoire_{1,2,3} (scripts/adapt_study.sh makes them, or the first lines of that
script alone). Keeps every elite's damaged distances in OUT_DIR/prior_tables_SEED.npz (about 3
minutes a map on 2 cores), so a second look runs no simulation.
"""
import itertools
import os
import pathlib
import statistics
import sys

import numpy as np

import hexgait
from adapt_gp_study import DAMAGES, LEGS, random_best
from adapt_landscape import GOAL_BEATS, GOAL_FRACTION, GOAL_TRIALS

KINDS = DAMAGES + ["lost"]  # adapt_gp_study's three, and the lost leg
SEEDS = (1, 2, 3)


def damaged_tables(out, seed, kinds=KINDS, name="prior_tables"):
    """{damage: every elite's distance on that damaged creature}, for every leg with each of
    KINDS, the descriptors and the intact distances of the map OUT/repertoire_SEED, cached in
    OUT/NAME_SEED.npz."""
    cache = out / f"{name}_{seed}.npz"
    if cache.exists():
        data = dict(np.load(cache))
        made_for = [str(k) for k in data.pop("kinds", [])]
        if made_for != list(kinds):  # a cache of other damages would answer another question
            made = f"made for the damages {made_for}" if made_for else "no record of its damages"
            sys.exit(f"{cache}: {made}, not {list(kinds)}; remove it to run them again")
    else:
        rep = out / f"repertoire_{seed}"
        if not (rep / "archive.json").exists():
            sys.exit(f"{rep}: no finished repertoire there (scripts/adapt_study.sh makes it)")
        frame = hexgait.load_archive(str(rep))
        measures = frame[[f"measures_{i}" for i in range(6)]].to_numpy()
        by_cell = dict(zip(frame["index"].to_numpy(), measures))
        data = {}
        for leg, kind in itertools.product(LEGS, kinds):
            damage = f"{leg}:{kind}"
            try:  # one trial: only every elite's damaged run is wanted
                a = hexgait.adapt(str(rep), damage=damage, seed=seed, trials=1)
            except ValueError as error:  # every elite falls: nothing to adapt to
                print(f"  {seed} {damage}: refused ({error})", file=sys.stderr)
                continue
            data["descriptors"] = np.array([by_cell[int(c)] for c in a["cells"]])
            data["intact"] = a["intact_distance"]
            data[damage] = a["damaged_distance"]
            print(f"  map {seed} {damage}: {len(a['cells'])} elites", file=sys.stderr, flush=True)
        partial = out / f"{name}_{seed}.partial.npz"  # renamed whole: never half a cache
        np.savez(partial, kinds=np.array(kinds), **data)
        os.replace(partial, cache)
    descriptors, intact = data.pop("descriptors"), data.pop("intact")
    return descriptors, intact, data


def correlations(intact, tables):
    """Pearson correlations of one damage's distances with the intact ones, with another
    damage's of the same leg, and with a damage of another leg."""
    names = list(tables)
    with_intact = [np.corrcoef(intact, tables[a])[0, 1] for a in names]
    same, other = [], []
    for a, b in itertools.combinations(names, 2):
        r = np.corrcoef(tables[a], tables[b])[0, 1]
        (same if a.split(":")[0] == b.split(":")[0] else other).append(r)
    return with_intact, same, other


def priors_for(answer, intact, tables):
    others = [name for name in tables if name != answer]
    fit = [np.corrcoef(tables[name], tables[answer])[0, 1] for name in others]
    return {
        "intact": intact,
        "library mean": np.mean([tables[name] for name in others], axis=0),
        "best of library": tables[others[int(np.argmax(fit))]],
        "the answer": tables[answer],
    }


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/adapt_study")
    cuts = {"after the stop rule": {}, f"at {GOAL_TRIALS} trials": {"stop": None,
                                                                     "trials": GOAL_TRIALS}}
    results = {}  # (cut, prior) -> [(kind, fraction of the best, trials, beats random)]
    ranking = {}  # prior -> [(kind, correlation with the answer, its first elites hold one)]
    corr_intact, corr_same, corr_other = [], [], []
    for seed in SEEDS:
        descriptors, intact, tables = damaged_tables(out, seed)
        a, b, c = correlations(intact, tables)
        corr_intact += a
        corr_same += b
        corr_other += c
        for answer in tables:
            damaged = tables[answer]
            worth = damaged >= GOAL_FRACTION * damaged.max()
            for prior_name, prior in priors_for(answer, intact, tables).items():
                kind = answer.split(":")[1]
                # How well the prior alone ranks the elites: its correlation with the answer,
                # and whether the elites it ranks first include one worth finding.
                top = np.argsort(-prior, kind="stable")[:GOAL_TRIALS]
                ranking.setdefault(prior_name, []).append(
                    (kind, np.corrcoef(prior, damaged)[0, 1], bool(worth[top].any())))
                for cut, flags in cuts.items():
                    r = hexgait.trial_and_error(descriptors, prior, damaged, **flags)
                    used = len(r["trials"])
                    adapted = r["trials"][-1]["best"]
                    beats = adapted > random_best(damaged, used, f"{seed}:{answer}")
                    results.setdefault((cut, prior_name), []).append(
                        (kind, adapted / damaged.max(), used, beats))
    med = statistics.median
    print(f"Correlation of two tables of every elite's distance (medians over "
          f"{len(SEEDS)} maps):\n")
    print("| a damaged creature's distances with | pairs | correlation (median) |")
    print("|---|---|---|")
    print(f"| the intact distances (the loop's prior) | {len(corr_intact)} | "
          f"{med(corr_intact):.2f} |")
    print(f"| another damage of the same leg | {len(corr_same)} | {med(corr_same):.2f} |")
    print(f"| a damage of another leg | {len(corr_other)} | {med(corr_other):.2f} |")
    print(f"\nEach prior alone (medians; 'its {GOAL_TRIALS} best': the runs in which the "
          f"{GOAL_TRIALS} elites it ranks first include one at >= {100 * GOAL_FRACTION:.0f}% "
          "of the best):\n")
    print(f"| prior | damages | runs | correlation with the answer | its {GOAL_TRIALS} best "
          "include one |")
    print("|---|---|---|---|---|")
    for prior_name, rows in ranking.items():
        for label, kinds in (("weak, locked, short", KINDS[:3]), ("all four", KINDS)):
            sub = [row for row in rows if row[0] in kinds]
            print(f"| {prior_name} | {label} | {len(sub)} | {med(r[1] for r in sub):.2f} | "
                  f"{sum(r[2] for r in sub)} |")
    print("\nThe library's loop (its defaults) with each prior; medians as a fraction of the best "
          "elite on the damaged creature:\n")
    print_loop_results(results)


def print_loop_results(results):
    """results: {(cut, prior): [(damage kind, fraction of the best, trials, beats random)]},
    as a Markdown table of medians over the weak, locked and short runs and over all four."""
    med = statistics.median
    print("| cut | prior | damages | runs | trials (median, max) | adapted | beats random |")
    print("|---|---|---|---|---|---|---|")
    for (cut, prior_name), rows in results.items():
        for label, kinds in (("weak, locked, short", KINDS[:3]), ("all four", KINDS)):
            sub = [row for row in rows if row[0] in kinds]
            print(f"| {cut} | {prior_name} | {label} | {len(sub)} | "
                  f"{med(r[2] for r in sub):g}, {max(r[2] for r in sub)} | "
                  f"{100 * med(r[1] for r in sub):.0f}% | {sum(r[3] for r in sub)} |")
    print(f"\nThe goals: {100 * GOAL_FRACTION:.0f}% within {GOAL_TRIALS} trials, beating random "
          f"elites in {GOAL_BEATS} of 54 runs (weak, locked, short).")


if __name__ == "__main__":
    main()
