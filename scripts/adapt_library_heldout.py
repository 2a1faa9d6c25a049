#!/usr/bin/env python3
"""Adaptation with a library of damages on maps it was never measured on (docs/results.md, "On
three new maps"). scripts/adapt_library_study.py chose the library loop's selection (the
nearest in gait) on map 1 of seeds 1-3 and measured it on all three; this script makes three
more maps the same way (20,000-evaluation MAP-Elites repertoires, seeds 4-6, as
scripts/adapt_study.sh makes seeds 1-3) and runs the goal study on them unchanged: every leg
with weak=0.2, locked and short=0.8, 54 runs, each adapted by hexgait.adapt(library=True), which
is `hexgait adapt --library` without its files, with the stop rule off for 20 trials, so one run
gives both cuts (the first 10 trials, and the trials where the stop rule first held). The
intact prior's loop on the same runs comes from hexgait.trial_and_error over the damaged
distances adapt() returns (the same trials as adapt() without a library; tests/python checks
that), and the random elites are drawn as scripts/adapt_library_study.py draws them.

    PYTHONPATH=build/python scripts/adapt_library_heldout.py [OUT_DIR]  (default out/adapt_study)

Writes OUT_DIR/repertoire_{4,5,6} when missing (about 4 minutes each on the 2-core machine) and
each run's result to OUT_DIR/heldout/SEED_LEG_KIND.json (about 70 s each), so an interrupted
study resumes where it stopped and a second look runs no simulation.
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys

import numpy as np

import hexgait
from adapt_gp_study import DAMAGES, LEGS, random_best
from adapt_landscape import GOAL_BEATS, GOAL_FRACTION, GOAL_TRIALS

SEEDS = (4, 5, 6)
EVALUATIONS = 20000  # scripts/adapt_study.sh's maps
MAX_TRIALS = 20  # the library loop's default limit: the stop rule's cut ends there


def ensure_map(hexgait_bin, rep, seed):
    """The repertoire scripts/adapt_common.sh's ensure_map makes, unless it is there."""
    if (rep / "repertoire.json").exists():
        return
    print(f"map {seed}: {EVALUATIONS} evaluations", file=sys.stderr, flush=True)
    subprocess.run([hexgait_bin, "repertoire", "--evaluations", str(EVALUATIONS), "--seed",
                    str(seed), "--no-movie", "--compare-ga", "0", "--quiet", "--out", str(rep)],
                   check=True, stdout=sys.stderr)  # its table is not this script's


def adapted(rep, seed, damage, cache):
    """adapt(library=True)'s trials, its stop rule's trials and every elite's damaged distance,
    and the intact prior's trials on the same damaged distances; cached in CACHE."""
    if cache.exists():
        return json.loads(cache.read_text())
    a = hexgait.adapt(str(rep), damage=damage, seed=seed, library=True, stop=None,
                      trials=MAX_TRIALS)
    frame = hexgait.load_archive(str(rep))
    by_cell = dict(zip(frame["index"].to_numpy(),
                       frame[[f"measures_{i}" for i in range(6)]].to_numpy()))
    descriptors = np.array([by_cell[int(c)] for c in a["cells"]])
    intact = hexgait.trial_and_error(descriptors, a["intact_distance"], a["damaged_distance"],
                                     stop=None, trials=MAX_TRIALS)
    record = {
        "library": [t["best"] for t in a["trials"]],
        "library_stop_rule_trials": a["stop_rule_trials"],
        "library_runs": a["library_runs"],
        "library_runs_possible": len(a["library"]) * len(a["cells"]),
        "priors": [t["prior"] for t in a["trials"]],
        "intact": [t["best"] for t in intact["trials"]],
        "intact_stop_rule_trials": intact["stop_rule_trials"],
        "damaged": a["damaged_distance"].tolist(),
    }
    partial = cache.with_suffix(".partial")  # renamed whole: never half a result
    partial.write_text(json.dumps(record))
    os.replace(partial, cache)
    return record


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", nargs="?", default="out/adapt_study", type=pathlib.Path,
                        help="the folder for repertoire_{4,5,6} and heldout/ "
                             "(default: out/adapt_study)")
    out = parser.parse_args().out
    hexgait_bin = os.environ.get("HEXGAIT_BIN", "build/hexgait")
    if not os.access(hexgait_bin, os.X_OK):
        sys.exit(f"{hexgait_bin}: not built (cmake --build build), or set HEXGAIT_BIN")
    (out / "heldout").mkdir(parents=True, exist_ok=True)
    rows = {}  # (cut, prior, seed) -> [(fraction of the best, trials, beats random)]
    shares = []
    for seed in SEEDS:
        rep = out / f"repertoire_{seed}"
        ensure_map(hexgait_bin, rep, seed)
        for leg in LEGS:
            for kind in DAMAGES:
                damage = f"{leg}:{kind}"
                cache = out / "heldout" / f"{seed}_{leg}_{kind.replace('=', '')}.json"
                try:
                    r = adapted(rep, seed, damage, cache)
                except ValueError as error:  # every elite falls: nothing to adapt to
                    print(f"  map {seed} {damage}: refused ({error})", file=sys.stderr)
                    continue
                print(f"  map {seed} {damage}: done", file=sys.stderr, flush=True)
                damaged = np.array(r["damaged"])
                shares.append(r["library_runs"] / r["library_runs_possible"])
                for prior in ("intact", "library"):
                    stop_at = r[f"{prior}_stop_rule_trials"] or MAX_TRIALS
                    for cut, n in (("after the stop rule", stop_at),
                                   (f"at {GOAL_TRIALS} trials", GOAL_TRIALS)):
                        best = r[prior][n - 1]
                        # The draw of scripts/adapt_library_study.py: one per run and count.
                        beats = best > random_best(damaged, n, f"{seed}:{damage}")
                        rows.setdefault((cut, prior, seed), []).append(
                            (best / damaged.max(), n, beats))
    med = statistics.median
    names = {"intact": "intact (the default)", "library": "nearest in gait (`--library`)"}
    print(f"Maps {', '.join(map(str, SEEDS))}, each leg weak=0.2, locked, short=0.8; medians as a "
          "fraction of the best elite on the damaged creature (the goals: "
          f"{100 * GOAL_FRACTION:.0f}% within {GOAL_TRIALS} trials, beating random elites in "
          f"{GOAL_BEATS} of 54 runs):\n")
    print("| cut | prior | map | runs | trials (median, max) | adapted | beats random |")
    print("|---|---|---|---|---|---|---|")
    for cut in ("after the stop rule", f"at {GOAL_TRIALS} trials"):
        for prior in ("intact", "library"):
            every = []
            for seed in SEEDS:
                got = rows.get((cut, prior, seed), [])
                every += got
                if got:
                    print(f"| {cut} | {names[prior]} | {seed} | {len(got)} | "
                          f"{med(g[1] for g in got):g}, {max(g[1] for g in got)} | "
                          f"{100 * med(g[0] for g in got):.0f}% | {sum(g[2] for g in got)} |")
            if every:
                print(f"| {cut} | {names[prior]} | all | {len(every)} | "
                      f"{med(g[1] for g in every):g}, {max(g[1] for g in every)} | "
                      f"**{100 * med(g[0] for g in every):.0f}%** | "
                      f"**{sum(g[2] for g in every)}** |")
    if shares:
        print(f"\nThe library's runs adapt made: a median {100 * med(shares):.1f}% of them "
              f"({100 * max(shares):.1f}% at most) over {len(shares)} runs.")


if __name__ == "__main__":
    main()
