"""What the landscape Intelligent Trial and Error searches is like, for scripts/adapt_gp_study.py
and scripts/adapt_legs_study.py: how many elites are worth finding on the damaged creature, how
well the loop's prior (each elite's intact distance) ranks them, and how smooth the damaged
distances are over the descriptors, which is what the GP's kernel assumes (the Pearson
correlation of each elite's distance with its nearest neighbour's, against the same for the
intact distances). And two ways to spend the goal's trials without a model: the share of runs in
which the elites that walked farthest intact include one worth finding, and the chance that as
many elites drawn at random do. Medians over the runs, printed as a Markdown table."""
import statistics

import numpy as np

# The adaptation goals (issue "Better maps, better recovery"): 85% of the best elite's distance on
# the damaged creature within 10 trials, beating as many random elites in 45 of 54 runs.
GOAL_FRACTION, GOAL_TRIALS, GOAL_BEATS = 0.85, 10, 45


def nearest_neighbours(points):
    """Each row's nearest other row (Euclidean), and how far it is."""
    gaps = np.linalg.norm(points[:, None, :] - points[None, :, :], axis=-1)
    np.fill_diagonal(gaps, np.inf)
    return gaps.argmin(axis=1), gaps.min(axis=1)


def print_landscape(runs):
    """runs: (descriptors (n x d), intact distances (n), damaged distances (n)) per adapt run."""
    share, prior_corr, near_damaged, near_intact, near_gap = [], [], [], [], []
    top_found, random_finds = 0, []
    for descriptors, intact, damaged in runs:
        worth = damaged >= GOAL_FRACTION * damaged.max()
        share.append(float(np.mean(worth)))
        top_found += bool(worth[np.argsort(-intact, kind="stable")[:GOAL_TRIALS]].any())
        # Drawn without replacement: 1 - C(n - worth, k) / C(n, k).
        n, good = len(damaged), int(worth.sum())
        miss = np.prod([(n - good - j) / (n - j) for j in range(min(GOAL_TRIALS, n))])
        random_finds.append(1 - miss)
        prior_corr.append(np.corrcoef(intact, damaged)[0, 1])
        nearest, gap = nearest_neighbours(descriptors)
        near_damaged.append(np.corrcoef(damaged, damaged[nearest])[0, 1])
        near_intact.append(np.corrcoef(intact, intact[nearest])[0, 1])
        near_gap.append(float(np.median(gap)))
    med = statistics.median
    print(f"\nThe landscape, medians over the {len(runs)} runs:\n")
    print(f"| elites at >= {100 * GOAL_FRACTION:.0f}% of the best damaged | correlation of intact and "
          "damaged distance | nearest neighbour's correlation, damaged / intact | descriptor gap "
          f"to the nearest elite | the {GOAL_TRIALS} best intact include one | {GOAL_TRIALS} random "
          "elites include one |")
    print("|---|---|---|---|---|---|")
    print(f"| {100 * med(share):.1f}% | {med(prior_corr):.2f} | {med(near_damaged):.2f} / "
          f"{med(near_intact):.2f} | {med(near_gap):.3f} | {top_found} of {len(runs)} runs | "
          f"{100 * med(random_finds):.0f}% |")
