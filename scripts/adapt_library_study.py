#!/usr/bin/env python3
"""Adaptation with a library of simulated damages, its prior picked by the trials
(docs/results.md, "A library of damages at several strengths"). The loop's prior is each elite's
intact distance, which ranks the gaits of a damaged creature weakly (correlation 0.12-0.15), and
scripts/adapt_prior_study.py found that no other damage of a 24-damage library predicts a
damaged creature better. A robot can bring a denser library: every leg with each damage at
several strengths, every elite simulated on each before it sets out; whatever the true damage
is, the library then holds damages like it, though never the damage itself. The loop starts
from the intact distances and, after every trial, takes as its prior the library member that
best explains the trials so far, chosen two ways: the likeliest (the largest marginal
likelihood of the GP given the distances walked), in the manner of adaptive prior selection
(Kaushik, Desreumaux and Mouret, Frontiers in Robotics and AI 6:151, 2020); and the nearest in
gait (the member whose duty factors at the tried elites lie nearest those the trials showed),
which is the library loop's own (hexgait.trial_and_error with library=, `hexgait adapt
--library`).

The library, per leg: weak=0.1, 0.2, 0.3 and 0.5, short=0.7, 0.8 and 0.9, locked and lost (54
damaged creatures a map, each elite run once on each by hexgait.adapt; cached in
OUT/library_tables_SEED.npz, and every elite's duty factors on each, by hexgait.Evaluator, in
OUT/library_duty_SEED.npz). The true damages are those of the other studies (weak=0.2, locked,
short=0.8 and lost on every leg of the three maps of scripts/adapt_study.sh: the 54 goal runs
and 18 more). Besides the intact prior alone, for each true damage, the likeliest and the
nearest in gait of two libraries:
  less the answer     the other 53 damages of that map and the intact distances (the
                      library `hexgait adapt --library` draws on);
  other damages only  the same without the true damage's kind on its leg at any strength (a
                      library that does not know this kind of injury to this leg);
and
  its member most like the answer, picked knowing it
                      the best correlation with the answer's distances, from the first trial:
                      the member a selection rule is after.
The GP, kernel, UCB, stop rule and units are the library loop's defaults (adapt/trial_and_error.h:
length scale 0.15, kappa 0.05, stop at 90% of the best prediction, 20 trials at most, distances
divided by the archive's best intact distance); with the intact prior alone this script's loop
makes the same trials as hexgait.trial_and_error, which it checks on every run.

    PYTHONPATH=build/python scripts/adapt_library_study.py [OUT_DIR]   (default out/adapt_study)

Needs OUT_DIR/repertoire_{1,2,3} (scripts/adapt_study.sh makes them, or the first lines of that
script alone). The tables took 27-32 minutes a map on the 2-core machine with other work
beside it, the duty factors 7-12 minutes more; a second look runs no simulation (seconds).
"""
import argparse
import os
import pathlib
import statistics
import sys

import numpy as np

import hexgait
from adapt_gp_study import random_best
from adapt_landscape import GOAL_TRIALS
from adapt_prior_study import KINDS, SEEDS, damaged_tables, print_loop_results

LIBRARY_KINDS = hexgait.damage_library_kinds  # the injuries of `hexgait adapt --library`
# The library loop's defaults (adapt/trial_and_error.h); check_against_library_loop finds it out
# on every run if they no longer are.
LENGTH_SCALE, KAPPA, STOP_FRACTION, MAX_TRIALS, NOISE = 0.15, 0.05, 0.9, 20, 0.001


def kind_of(damage):
    """'left_rear:weak=0.2' -> ('left_rear', 'weak')."""
    leg, kind = damage.split(":")
    return leg, kind.split("=")[0]


def likeliest(members, x, measured, tried):
    """The member whose prior means at the tried elites (rows x) leave the least unlikely
    residuals r under the GP: the smallest r' K^-1 r, K the kernel over x plus the noise (the
    same for every member, so its log-determinant cancels); the first of equals. The library's
    GP gives it: fitted to r, its posterior mean m at x is r - noise K^-1 r."""
    gp = hexgait.GaussianProcess(length_scale=LENGTH_SCALE, noise=NOISE)
    scores = []
    for prior in members:
        r = measured - prior[tried]
        gp.fit(x, r)
        scores.append(r @ (r - gp.predict(x)[0]) / NOISE)
    return int(np.argmin(scores))


def adapt_with_library(descriptors, scale, members, damaged, trials=MAX_TRIALS, stop=True):
    """The library loop with its prior chosen among MEMBERS (arrays of distances, members[0]
    the prior before any trial) after every trial, distances divided by SCALE (the archive's
    best intact distance). Returns the trials (elite, distance, best) and the number after
    which the stop rule held (0: never)."""
    scaled = [m / scale for m in members]
    gp = hexgait.GaussianProcess(length_scale=LENGTH_SCALE, noise=NOISE)
    tried, measured, result, stop_at = [], [], [], 0
    chosen = 0
    while True:
        if tried:
            x = descriptors[tried]
            y = np.array(measured)
            chosen = likeliest(scaled, x, y, tried)
            gp.fit(x, y, scaled[chosen][tried])
            mean, sd = gp.predict(descriptors, scaled[chosen])
        else:  # no trial yet: the prior, with the kernel's whole variance (1) everywhere
            mean, sd = scaled[0], np.ones(len(descriptors))
        mean, sd = scale * np.asarray(mean), scale * np.asarray(sd)
        if not stop_at and result and result[-1][2] >= STOP_FRACTION * mean.max():
            stop_at = len(result)
            if stop:
                break
        if len(result) >= trials:
            break
        nxt = int(np.argmax(mean + KAPPA * sd))
        best = max(damaged[nxt], result[-1][2]) if result else damaged[nxt]
        result.append((nxt, damaged[nxt], best))
        tried.append(nxt)
        measured.append(damaged[nxt] / scale)
    return result, stop_at


def check_against_library_loop(descriptors, intact, damaged):
    """With the intact prior alone this loop must be the library's."""
    ours, _ = adapt_with_library(descriptors, intact.max(), [intact], damaged)
    theirs = hexgait.trial_and_error(descriptors, intact, damaged)["trials"]
    if [t[0] for t in ours] != [t["elite"] for t in theirs]:
        sys.exit("this script's loop no longer makes the library loop's trials: mend it first")


def gait_tables(out, seed, tables):
    """{damage: every elite's duty factors (elites x 6) on that damaged creature}, for the
    damages of TABLES (their distances), cached in OUT/library_duty_SEED.npz. Run as
    hexgait.adapt runs every elite (in double, ending at a fall); the distances must come out
    as TABLES holds them."""
    cache = out / f"library_duty_{seed}.npz"
    if cache.exists():
        data = dict(np.load(cache))
        made_for = [str(k) for k in data.pop("damages", [])]
        if made_for != list(tables):
            sys.exit(f"{cache}: made for other damages than {out}/library_tables_{seed}.npz; "
                     "remove it to run them again")
        return data
    frame = hexgait.load_archive(str(out / f"repertoire_{seed}"))
    genes = frame[[c for c in frame.columns if c.startswith("solution_")]].to_numpy()
    data = {}
    for damage, distances in tables.items():
        evaluator = hexgait.Evaluator(creature=hexgait.Creature(damage=damage),
                                      precision="double", stop_at_fall=True)
        runs = evaluator.evaluate(genes)
        if not np.array_equal(runs["distance"], distances):
            sys.exit(f"map {seed} {damage}: the elites' runs no longer walk the cached distances")
        data[damage] = runs["duty_factors"]
        print(f"  map {seed} {damage}: duty factors", file=sys.stderr, flush=True)
    partial = out / f"library_duty_{seed}.partial.npz"  # renamed whole: never half a cache
    np.savez(partial, damages=np.array(list(tables)), **data)
    os.replace(partial, cache)
    return data


def library_names(answer, tables):
    """The two libraries a true damage is adapted with: every other damage of the map, and
    those without the true damage's kind on its leg at any strength."""
    less_answer = [name for name in tables if name != answer]
    return {"less the answer": less_answer,
            "other damages only": [n for n in less_answer if kind_of(n) != kind_of(answer)]}


def libraries_for(answer, intact, tables):
    names = library_names(answer, tables)
    less_answer = names["less the answer"]
    fit = [np.corrcoef(tables[name], tables[answer])[0, 1] for name in less_answer]
    return {
        "intact only (the default)": [intact],
        "likeliest, less the answer": [intact] + [tables[n] for n in less_answer],
        "likeliest, other damages only": [intact] + [tables[n] for n in names["other damages only"]],
        "its member most like the answer, picked knowing it": [
            tables[less_answer[int(np.argmax(fit))]]],
    }, max(fit)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", nargs="?", default="out/adapt_study", type=pathlib.Path,
                        help="the folder with repertoire_{1,2,3} (default: out/adapt_study)")
    out = parser.parse_args().out
    results = {}  # (cut, library) -> [(kind, fraction of the best, trials, beats random)]
    closest = {}  # kind -> the best correlation of a library member with the answer
    maps = {}  # (cut, library, seed) -> the rows of results from that map
    diagnoses = {}  # (cut, library, kind) -> [(its leg, its leg and kind, fraction of the best)]
    read = {}  # (cut, library) -> [the share of the library's runs the loop read]
    for seed in SEEDS:
        descriptors, intact, tables = damaged_tables(out, seed, LIBRARY_KINDS, "library_tables")
        gaits = gait_tables(out, seed, tables)
        for answer in tables:
            kind = answer.split(":")[1]
            if kind not in KINDS:
                continue  # a library member only
            damaged = tables[answer]

            def outcome(walked, kind=kind, damaged=damaged, run=f"{seed}:{answer}"):
                """A loop's row: its best as a fraction of the best elite, its trials, and
                whether it beat as many random elites."""
                return (kind, walked[-1] / damaged.max(), len(walked),
                        walked[-1] > random_best(damaged, len(walked), run))

            check_against_library_loop(descriptors, intact, damaged)
            libraries, fit = libraries_for(answer, intact, tables)
            closest.setdefault(kind, []).append(fit)
            # The library loop's own selection (hexgait adapt --library): the member whose
            # gaits, at the elites tried, look most like what the trials showed.
            by_gait = {f"nearest in gait, {name}": {n: (tables[n], gaits[n]) for n in names}
                       for name, names in library_names(answer, tables).items()}
            cuts = (("after the stop rule", {}, {}),
                    (f"at {GOAL_TRIALS} trials", {"trials": GOAL_TRIALS, "stop": False},
                     {"trials": GOAL_TRIALS, "stop": None}))
            for cut, flags, library_flags in cuts:
                for library, members in libraries.items():
                    trials, _ = adapt_with_library(descriptors, intact.max(), members, damaged,
                                                   **flags)
                    walked = [t[2] for t in trials]
                    results.setdefault((cut, library), []).append(outcome(walked))
                    maps.setdefault((cut, library, seed), []).append(outcome(walked))
                for library, members in by_gait.items():
                    loop = hexgait.trial_and_error(descriptors, intact, damaged, library=members,
                                                   shown=gaits[answer], **library_flags)
                    walked = [t["best"] for t in loop["trials"]]
                    results.setdefault((cut, library), []).append(outcome(walked))
                    read.setdefault((cut, library), []).append(
                        loop["library_runs"] / (len(members) * len(intact)))
                    maps.setdefault((cut, library, seed), []).append(outcome(walked))
                    prior = loop["trials"][-1]["prior"]  # the diagnosis the last trial ran under
                    diagnoses.setdefault((cut, library, kind), []).append(
                        (prior.split(":")[0] == answer.split(":")[0],
                         prior != "intact" and kind_of(prior) == kind_of(answer),
                         walked[-1] / damaged.max()))
    med = statistics.median
    print("How like the answer the library's closest member is (the best Pearson correlation of "
          "its distances with the answer's; medians):\n")
    print("| damage | runs | closest member's correlation |")
    print("|---|---|---|")
    for kind, fits in closest.items():
        print(f"| {kind} | {len(fits)} | {med(fits):.2f} |")
    print()
    print("Adaptation with a library of damages; medians as a fraction of the best elite on the "
          "damaged creature:\n")
    print_loop_results(results)
    print("\nMap by map (the library loop's selection was chosen on map 1's runs before "
          "maps 2 and 3 were run on the library); weak, locked and short:\n")
    print("| cut | prior | map | runs | adapted | beats random |")
    print("|---|---|---|---|---|---|")
    for (cut, library, seed), rows in maps.items():
        if library.startswith(("intact", "nearest in gait, less")):
            goal = [r for r in rows if r[0] in KINDS[:3]]
            print(f"| {cut} | {library} | {seed} | {len(goal)} | "
                  f"{100 * med(r[1] for r in goal):.0f}% | {sum(r[3] for r in goal)} |")
    print("\nThe library loop's diagnosis: the prior its last trial ran under, a damage to the "
          "damaged leg, and of its kind at another strength; adapted, median fraction of the "
          "best elite:\n")
    print("| cut | library | damage | runs | the damaged leg | its kind too | adapted |")
    print("|---|---|---|---|---|---|---|")
    for (cut, library, kind), rows in diagnoses.items():
        print(f"| {cut} | {library} | {kind} | {len(rows)} | {sum(r[0] for r in rows)} | "
              f"{sum(r[1] for r in rows)} | {100 * med(r[2] for r in rows):.0f}% |")
    print("\nThe library's runs the loop read (what `hexgait adapt --library` simulates of the "
          "library: each member at the tried elites where it could still be the nearest, every "
          "elite on the members taken as the prior), over all four damages:\n")
    print("| cut | library | runs | median | largest |")
    print("|---|---|---|---|---|")
    for (cut, library), shares in read.items():
        print(f"| {cut} | {library} | {len(shares)} | {100 * med(shares):.1f}% | "
              f"{100 * max(shares):.1f}% |")


if __name__ == "__main__":
    main()
