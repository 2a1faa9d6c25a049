#!/usr/bin/env python3
"""How Intelligent Trial and Error's settings decide adaptation (docs/results.md, "The loop's
settings"): every leg x three damages on the repertoires of scripts/adapt_study.sh, with the
GP's normalisation, kappa, length scale and stop fraction varied.

Each (repertoire, damage) is run once by hexgait.adapt(), which runs every elite on the damaged
creature; the loop itself (hexgait.trial_and_error, the library's loop) then runs for every
setting with those distances as its trials: a trial is one deterministic simulation of an elite
on the damaged creature, the same number adapt() measures. Each run's adapted distance is a
fraction of the best elite's on the damaged creature; "random elites" is the best of as many
elites as the loop used trials, drawn without replacement (one seeded draw per run and number
of trials).

    PYTHONPATH=build/python scripts/adapt_gp_study.py [OUT_DIR]   (default out/adapt_study)

Needs OUT_DIR/repertoire_{1,2,3} (scripts/adapt_study.sh makes them). Writes OUT_DIR/gp_study.csv
and prints a Markdown table, best settings first, then what the landscape the loop searches is
like (how many elites are worth finding, and how smooth their damaged distances are).
"""
import csv
import itertools
import pathlib
import statistics
import sys
import zlib

import numpy as np

import hexgait
from adapt_landscape import GOAL_BEATS, GOAL_FRACTION, GOAL_TRIALS, print_landscape

LEGS = ["right_front", "right_middle", "right_rear", "left_front", "left_middle", "left_rear"]
DAMAGES = ["weak=0.2", "locked", "short=0.8"]
NORMALISE = ["none", "best", "spread"]
KAPPA = [0.05, 0.2, 1.0]
LENGTH_SCALE = [0.4, 0.3, 0.2, 0.15, 0.1]
STOP = [0.9, 0.95]


def damaged_runs(out):
    """(name, descriptors, prior, damaged) for every repertoire and damage, kept in
    OUT/gp_study_runs.npz so that another look at the settings does not run them again."""
    cache = out / "gp_study_runs.npz"
    if cache.exists():
        data = np.load(cache)
        return [(str(name), data[f"d{i}"], data[f"p{i}"], data[f"x{i}"])
                for i, name in enumerate(data["names"])]
    runs = []
    for seed in (1, 2, 3):
        rep = out / f"repertoire_{seed}"
        frame = hexgait.load_archive(str(rep))
        measures = frame[[f"measures_{i}" for i in range(6)]].to_numpy()
        by_cell = dict(zip(frame["index"].to_numpy(), measures))
        for leg, kind in itertools.product(LEGS, DAMAGES):
            damage = f"{leg}:{kind}"
            try:
                a = hexgait.adapt(str(rep), damage=damage, seed=seed)
            except ValueError as error:  # every elite falls: nothing to adapt to
                print(f"  {seed} {damage}: refused ({error})", file=sys.stderr)
                continue
            descriptors = np.array([by_cell[int(c)] for c in a["cells"]])
            runs.append((f"{seed}:{damage}", descriptors, a["intact_distance"],
                         a["damaged_distance"]))
            print(f"  {seed} {damage}: {len(a['cells'])} elites", file=sys.stderr)
    arrays = {"names": np.array([r[0] for r in runs])}
    for i, (_, descriptors, prior, damaged) in enumerate(runs):
        arrays.update({f"d{i}": descriptors, f"p{i}": prior, f"x{i}": damaged})
    np.savez(cache, **arrays)
    return runs


def random_best(damaged, count, name):
    # One draw per run and count, whatever the setting: settings that use as many trials face
    # the same random elites.
    rng = np.random.default_rng(zlib.crc32(f"{name} {count}".encode()))
    return damaged[rng.choice(len(damaged), size=min(count, len(damaged)), replace=False)].max()


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/adapt_study")
    runs = damaged_runs(out)
    rows = []
    for normalise, kappa, scale, stop in itertools.product(NORMALISE, KAPPA, LENGTH_SCALE, STOP):
        fractions, trials, beats = [], [], 0
        for name, descriptors, prior, damaged in runs:
            r = hexgait.trial_and_error(descriptors, prior, damaged, normalise=normalise,
                                        kappa=kappa, length_scale=scale, stop=stop)
            used = len(r["trials"])
            adapted = r["trials"][-1]["best"]
            best = damaged.max()
            fractions.append(adapted / best)
            trials.append(used)
            beats += int(adapted > random_best(damaged, used, name))
        rows.append({
            "normalise": normalise, "kappa": kappa, "length_scale": scale, "stop": stop,
            "runs": len(runs), "trials_median": statistics.median(trials),
            "trials_max": max(trials), "adapted_median": statistics.median(fractions),
            "beats_random": beats,
            "meets_goals": bool(statistics.median(fractions) >= GOAL_FRACTION and
                                statistics.median(trials) <= GOAL_TRIALS and beats >= GOAL_BEATS),
        })
    with open(out / "gp_study.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    rows.sort(key=lambda r: (-r["meets_goals"], -r["adapted_median"], r["trials_median"]))
    print(f"{len(runs)} runs per setting (3 repertoires x 6 legs x 3 damages, less refusals)\n")
    print("| normalise | kappa | length scale | stop | trials (median, max) | adapted | "
          "beats random | meets the goals |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['normalise']} | {r['kappa']:g} | {r['length_scale']:g} | {r['stop']:g} | "
              f"{r['trials_median']:g}, {r['trials_max']} | {100 * r['adapted_median']:.0f}% | "
              f"{r['beats_random']} / {r['runs']} | {'yes' if r['meets_goals'] else 'no'} |")
    print_landscape([(d, p, x) for _, d, p, x in runs])


if __name__ == "__main__":
    main()
