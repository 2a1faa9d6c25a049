#!/usr/bin/env python3
"""A creature of 1,000 particles (or PARTICLES) for the size tests and the step-cost
measurement: the hexapod with beads hung from its particles, each tied by two springs (polygons
keep their skin vertices, whose indices move).

  make_big_creature.py HEXAPOD_JSON OUT_JSON [PARTICLES]
"""
import json
import sys

d = json.load(open(sys.argv[1]))
n0 = len(d["particles"])
added = (int(sys.argv[3]) if len(sys.argv) > 3 else 1000) - n0
for poly in d["polygons"]:  # a vertex past the particles is a skin vertex: its index moves
    poly["vertices"] = [v + added if v >= n0 else v for v in poly["vertices"]]
for i in range(added):
    a, b = i % n0, (i + 1) % n0
    pa, pb = d["particles"][a]["position"], d["particles"][b]["position"]
    d["particles"].append({"name": f"bead{i}", "mass": 0.01,
                           "position": [(pa[0] + pb[0]) / 2 + 0.001 * (i + 1),
                                        (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2 + 0.5]})
    for j, other in enumerate((a, b)):
        d["springs"].append({"name": f"bead{i}_{j}", "ends": [other, n0 + i], "stiffness": 10.0,
                             "damping": 0.1, "leg": None, "motor": False})
json.dump(d, open(sys.argv[2], "w"))
