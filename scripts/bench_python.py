#!/usr/bin/env python3
"""The Python module's overhead: Evaluator.evaluate() on 16 creatures against the same
evaluations inside `hexgait evolve`.

evolve runs --generations generations of 16 creatures (--elites 0, so every generation
evaluates all 16) and records each generation's wall time in run.json; the module evaluates 16
random genomes per call, as many calls, with the same time, precision and threads. Both are
reported as the median time per generation (per call), and their ratio; the module must stay
within 5% (a ratio at most 1.05). Run it on a quiet machine:

  PYTHONPATH=build/python python3 scripts/bench_python.py [--time 200] [--generations 15]
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import hexgait


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--time", type=float, default=200.0, help="simulated time per creature")
    parser.add_argument("--generations", type=int, default=15, help="generations (and calls)")
    parser.add_argument("--threads", type=int, default=0, help="threads (0: all)")
    parser.add_argument("--precision", default="double", choices=["double", "float"])
    parser.add_argument("--hexgait", default="build/hexgait", help="the hexgait binary")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as folder:
        out = pathlib.Path(folder) / "run"
        subprocess.run([args.hexgait, "evolve", "--population", "16", "--elites", "0",
                        "--generations", str(args.generations), "--time", str(args.time),
                        "--threads", str(args.threads), "--precision", args.precision,
                        "--seed", "1", "--quiet", "--out", str(out)], check=True)
        history = json.loads((out / "run.json").read_text())["history"]
    evolve = [g["seconds"] for g in history if g["evaluations"] == 16]

    evaluator = hexgait.Evaluator(time=args.time, threads=args.threads, precision=args.precision)
    rng = np.random.default_rng(1)
    module = []
    for _ in range(len(evolve)):
        genomes = rng.integers(-2, 3, size=(16, evaluator.genes), dtype=np.int8)
        start = time.perf_counter()
        evaluator.evaluate(genomes)
        module.append(time.perf_counter() - start)

    e, m = statistics.median(evolve), statistics.median(module)
    cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo")
                if line.startswith("model name")), "unknown CPU")
    print(f"CPU: {cpu}; {args.precision}, time {args.time:g}, {evaluator!r}")
    print(f"evolve, 16 creatures per generation: median {e * 1e3:.1f} ms over {len(evolve)}")
    print(f"Evaluator.evaluate, 16 creatures:    median {m * 1e3:.1f} ms over {len(module)}")
    print(f"ratio module / evolve: {m / e:.3f} ({'within' if m / e <= 1.05 else 'over'} 5%)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
