#!/usr/bin/env python3
"""Writes the built-in creatures and their motor programs into assets/:

  hexapod.json + metachronal.json          the default creature ("hexapod") and its program
  wedge.json   + wedge_metachronal.json    the first creature ("wedge"), kept unchanged

The creatures are data; this script is how that data was made, so every number in it can be
traced to a named constant here. Re-run it after changing a constant:
    python3 scripts/make_assets.py
--set NAME=VALUE overrides a hexapod constant, --set wedge.NAME=VALUE a wedge constant (for
parameter studies: scripts/sensitivity.sh). See docs/model.md for why each value is what it is.
"""
import argparse
import json
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

# Both creatures share one topology (docs/model.md, "The creature"): 8 body particles (4 belly
# corners, 2 ridge ends on the midline, 2 flanks), 20 body springs, 6 feet, 20 leg springs.
# Length unit: 1 = half the body length; x points along the walk, z up, y to the left.

# --- hexapod: the default. Body longer than wide, wider than tall, held clearly above the
# ground on six splayed legs. The values come from a random search for a creature that reads
# as a hexapod and still shows the paper's result (the unoptimised program rolls it over early;
# the GA finds gaits that do not); docs/model.md, "How the constants were chosen".
HEXAPOD = {
    # Geometry.
    "BODY_X": 1.0,          # belly corners and ridge ends at x = +-BODY_X (body length 2)
    "BELLY_Y": 0.3249,      # belly corners at y = +-BELLY_Y: the body is 0.65 wide
    "BELLY_Z": 1.0361,      # belly height when standing: clearly above the ground
    "RIDGE_Z": 1.5607,      # ridge height: the body is 0.52 tall (< 0.65 wide < 2 long)
    "FLANK_X": 0.0207,      # flank particles (the widest point) at x = FLANK_X,
    "FLANK_Y": 0.4268,      # y = +-FLANK_Y
    "FLANK_Z": 1.3634,      # and this height
    "FOOT_X": 1.2639,       # front and rear feet at x = +-FOOT_X: just beyond the body's ends
    "FOOT_Y": 0.7199,       # front and rear feet at y = -+FOOT_Y: outside the body (0.43)
    "MIDDLE_FOOT_Y": 0.7206,  # middle feet at x = 0, y = -+MIDDLE_FOOT_Y
    # Masses. The centre of mass sits 1.5x higher than the stance is half-wide, which is what
    # lets a growing yaw-and-shear roll the body over (a lower one never fell).
    "FRONT_BELLY_MASS": 1.0,
    "REAR_BELLY_MASS": 0.6899,
    "RIDGE_MASS": 0.6888,   # each ridge end
    "FLANK_MASS": 1.3248,   # the heaviest particles, high on the body's sides
    "FOOT_MASS": 0.2,
    # Springs. Damping is given directly (time constant c/k: 0.01 body, 0.062 legs).
    "BODY_K": 600.0,        # rigid truss: its fastest mode sets the Euler step margin
    "BODY_DAMPING": 6.0,
    "LEG_K": 23.121,        # soft legs: a walking creature's slow, swaying modes
    "LEG_DAMPING": 1.4428,
    # Leg ties: each leg only to body particles on its own side ({s}) or on the midline.
    "TIES": {
        "rear": ["front_belly_{s}", "rear_belly_{s}", "flank_{s}"],
        "middle": ["flank_{s}", "front_belly_{s}", "rear_belly_{s}", "front_ridge"],
        "front": ["front_belly_{s}", "rear_belly_{s}", "flank_{s}"],
    },
    "PHYSICS": {
        "gravity": 0.1911,
        "ground_stiffness": 400.0,
        "ground_damping": 8.0,
        "friction": 0.8078,
        "slip_velocity": 0.02,
        # The belly stands at 1.04: only a creature lying on the ground has a body particle
        # below 0.05; the tilt test catches a roll-over first.
        "fall_height": 0.05,
        "fall_tilt_degrees": 45.0,
    },
    # Motor program.
    "CYCLE": 66.0,          # time units per gait cycle (1000 time units ~ 15 cycles, as the paper)
    "STRIDE": 0.6824,       # foot travel relative to the body during stance
    "LIFT": 0.3985,         # swing height
    "GENE_STEP": 0.01,      # rest-length change per gene unit
    # Time for a rest length to reach a new instruction's value. The search found 6.3541; we use
    # 6.35, on the step grid of every dt we run (0.01 down to 0.000625), so the step-based
    # controller and the continuous schedule the reference solution uses agree exactly.
    "TRANSITION": 6.35,
    "SWING_LEAD": 0.0,      # a leg lifts this fraction of a slot before the previous leg lands
    "SWING_FORWARD": 0.3,   # swing target's forward offset, as a fraction of the stride
    # Skins (rendering only): each leg is drawn as a tapered limb, see leg_skins().
    "SKIN": True,
    "ROOT_ON_BELLY": 0.6,   # the limb's root is on the belly-flank edge, this far from the flank
    "ROOT_RADIUS": 0.08,    # limb half-thickness at the root
    "KNEE_RADIUS": 0.06,    # and at the knee; the limb ends in a point at the foot
    "KNEE_OUT": 0.7,        # the knee is this fraction of the way from the root to the foot,
    "KNEE_UP": 0.3,         # this much above the root (an insect's leg rises, then drops)
    "KNEE_FOLLOWS_FOOT": 0.5,  # share of the knee's motion that follows the foot (rest: body)
}

# --- wedge: the first creature, unchanged (same physics, same bits). A tall narrow wedge whose
# feet stand inside the body's width and whose front/rear legs tie across the body.
WEDGE = {
    "BODY_X": 1.0,
    "BELLY_Y": 0.5,
    "BELLY_Z": 0.6,
    "RIDGE_Z": 2.4,
    "FLANK_X": 0.0,
    "FLANK_Y": 0.6,
    "FLANK_Z": 1.68,
    "FOOT_X": 1.4,
    "FOOT_Y": 0.35,
    "MIDDLE_FOOT_Y": 0.65,
    "FRONT_BELLY_MASS": 1.0,
    "REAR_BELLY_MASS": 1.0,
    "RIDGE_MASS": 1.0,
    "FLANK_MASS": 1.0,
    "FOOT_MASS": 0.2,
    "BODY_K": 600.0,
    "BODY_DAMPING": 6.0,     # 0.01 * BODY_K
    "LEG_K": 25.0,
    "LEG_DAMPING": 2.5,      # 0.1 * LEG_K: leg springs are damped more, their slow modes matter
    # Chosen for well-conditioned tripods ({o}: the other side): the unit vectors from the body
    # to the foot span 3-D well, so a foot's position relative to the body is firmly set.
    "TIES": {
        "rear": ["front_belly_{s}", "rear_belly_{o}", "rear_ridge"],
        "middle": ["flank_{s}", "flank_{o}", "front_belly_{o}", "rear_belly_{o}"],
        "front": ["rear_belly_{s}", "front_belly_{o}", "front_ridge"],
    },
    "PHYSICS": {
        "gravity": 0.2,
        "ground_stiffness": 400.0,
        "ground_damping": 8.0,
        "friction": 0.8,
        "slip_velocity": 0.02,
        "fall_height": 0.2,
        "fall_tilt_degrees": 45.0,
    },
    "CYCLE": 66.0,
    "STRIDE": 0.5,
    "LIFT": 0.3,
    "GENE_STEP": 0.01,
    "TRANSITION": 8.0,
    "SWING_LEAD": 0.0,
    "SWING_FORWARD": 0.3,
    "SKIN": False,           # legs drawn as the triangles between the foot and its anchors
}

# The body truss: the edges of the carapace (belly rectangle, ridge, belly corners to the ridge
# ends, flanks to their neighbours) plus the two belly diagonals and the bar between the flanks.
# 20 bars, mirror-symmetric, rigidity rank 18 = 3 * 8 - 6 (checked by the tests). A plain
# 8-corner box cannot be braced both rigidly and mirror-symmetrically with 20 bars: every K4 on
# two mirror pairs is planar. Particles on the mirror plane (the ridge) avoid it.
BARS = [("rear_belly_right", "front_belly_right"), ("front_belly_right", "front_belly_left"),
        ("front_belly_left", "rear_belly_left"), ("rear_belly_left", "rear_belly_right"),
        ("rear_ridge", "front_ridge"),
        ("rear_belly_right", "rear_ridge"), ("rear_belly_left", "rear_ridge"),
        ("front_belly_right", "front_ridge"), ("front_belly_left", "front_ridge")]
for _side in ("right", "left"):
    for _other in (f"rear_belly_{_side}", f"front_belly_{_side}", "rear_ridge", "front_ridge"):
        BARS.append((f"flank_{_side}", _other))
BARS += [("rear_belly_right", "front_belly_left"), ("front_belly_right", "rear_belly_left"),
         ("flank_right", "flank_left")]

# Carapace faces, counter-clockwise seen from outside.
FACES = [["rear_belly_right", "rear_belly_left", "front_belly_left", "front_belly_right"],
         ["front_belly_right", "front_belly_left", "front_ridge"],
         ["rear_belly_left", "rear_belly_right", "rear_ridge"],
         ["rear_belly_right", "front_belly_right", "flank_right"],
         ["front_belly_right", "front_ridge", "flank_right"],
         ["front_ridge", "rear_ridge", "flank_right"],
         ["rear_ridge", "rear_belly_right", "flank_right"],
         ["front_belly_left", "rear_belly_left", "flank_left"],
         ["front_ridge", "front_belly_left", "flank_left"],
         ["rear_ridge", "front_ridge", "flank_left"],
         ["rear_belly_left", "rear_ridge", "flank_left"]]


def body_particles(c):
    """Belly corners, the ridge (on the mirror plane) and the two flanks: (name, position, mass)."""
    x, by, bz = c["BODY_X"], c["BELLY_Y"], c["BELLY_Z"]
    return [
        ("rear_belly_right", (-x, -by, bz), c["REAR_BELLY_MASS"]),
        ("front_belly_right", (x, -by, bz), c["FRONT_BELLY_MASS"]),
        ("front_belly_left", (x, by, bz), c["FRONT_BELLY_MASS"]),
        ("rear_belly_left", (-x, by, bz), c["REAR_BELLY_MASS"]),
        ("rear_ridge", (-x, 0.0, c["RIDGE_Z"]), c["RIDGE_MASS"]),
        ("front_ridge", (x, 0.0, c["RIDGE_Z"]), c["RIDGE_MASS"]),
        ("flank_right", (c["FLANK_X"], -c["FLANK_Y"], c["FLANK_Z"]), c["FLANK_MASS"]),
        ("flank_left", (c["FLANK_X"], c["FLANK_Y"], c["FLANK_Z"]), c["FLANK_MASS"]),
    ]


def add(a, b, s=1.0):
    return [a[i] + s * b[i] for i in range(3)]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = sum(v * v for v in a) ** 0.5
    return [v / n for v in a]


def barycentric(point, corners):
    """Affine weights w (sum 1) with sum w_i corners_i = point, for 4 non-coplanar corners."""
    # Solve [c1-c0 c2-c0 c3-c0] u = point - c0 by Cramer's rule; w = (1 - sum u, u).
    cols = [sub(corners[i], corners[0]) for i in (1, 2, 3)]
    rhs = sub(point, corners[0])

    def det(a, b, c):
        return (a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) +
                c[0] * (a[1] * b[2] - a[2] * b[1]))

    d = det(*cols)
    u = [det(rhs, cols[1], cols[2]) / d, det(cols[0], rhs, cols[2]) / d,
         det(cols[0], cols[1], rhs) / d]
    return [1.0 - sum(u)] + u


def leg_skins(c, side, part, foot, pos, idx, skins, base):
    """A tapered limb for one leg, as skin vertices (rendering only) and polygons.

    The root is a small triangle on the body (body-fixed: an affine blend of four body particles
    of the leg's own side and the midline); the knee is a smaller triangle above and outside the
    root, half following the body and half the foot; the limb ends in a point at the foot. A
    point fixed to a rigid body is an affine combination of four of its particles, so some
    weights are negative: a skin vertex may extrapolate (docs/model.md, "Polygons").
    """
    s = side
    end = "front" if part == "front" else "rear"
    frame = [idx[f"front_belly_{s}"], idx[f"rear_belly_{s}"], idx[f"flank_{s}"], idx["front_ridge"]]
    corners = [pos[i] for i in frame]
    belly = pos[idx[f"{end}_belly_{s}"]] if part != "middle" else None
    flank = pos[idx[f"flank_{s}"]]
    if part == "middle":  # middle legs root below the flank, on the belly edge's midpoint
        belly = [0.5 * (pos[idx[f"front_belly_{s}"]][i] + pos[idx[f"rear_belly_{s}"]][i])
                 for i in range(3)]
    t = c["ROOT_ON_BELLY"]
    root = [t * belly[i] + (1 - t) * flank[i] for i in range(3)]
    foot_pos = pos[foot]
    knee = add(root, sub(foot_pos, root), c["KNEE_OUT"])
    knee[2] = root[2] + c["KNEE_UP"]
    # A cross-section triangle around a centre, perpendicular to the limb's axis there.
    def ring(centre, axis, radius):
        side_dir = unit(cross(axis, [0.0, 0.0, 1.0]))
        up_dir = unit(cross(side_dir, axis))
        return [add(centre, up_dir, radius),
                add(add(centre, side_dir, 0.866 * radius), up_dir, -0.5 * radius),
                add(add(centre, side_dir, -0.866 * radius), up_dir, -0.5 * radius)]

    rings = []
    a = c["KNEE_FOLLOWS_FOOT"]
    for name, centre, axis, radius in (("root", root, sub(knee, root), c["ROOT_RADIUS"]),
                                       ("knee", knee, sub(foot_pos, root), c["KNEE_RADIUS"])):
        ids = []
        for j, p in enumerate(ring(centre, unit(axis), radius)):
            if name == "root":
                weights = list(zip(frame, barycentric(p, corners)))
            else:  # p = a * foot + (1 - a) * q, with q fixed to the body
                q = [(p[i] - a * foot_pos[i]) / (1 - a) for i in range(3)]
                weights = [(f, (1 - a) * w) for f, w in zip(frame, barycentric(q, corners))]
                weights.append((foot, a))
            ids.append(base + len(skins))
            skins.append({"name": f"{side}_{part}.{name}{j}",
                          "blend": [[i, round(w, 12)] for i, w in weights]})
        rings.append(ids)
    r, k = rings
    polygons = []
    for j in range(3):
        n = (j + 1) % 3
        polygons.append({"vertices": [r[j], r[n], k[n], k[j]], "part": "leg"})
        polygons.append({"vertices": [k[j], k[n], foot], "part": "leg"})
    return polygons


def fix_weight_sums(skins):
    """Rounded weights: put the rounding error on the largest weight so each sums to 1."""
    for s in skins:
        total = sum(w for _, w in s["blend"])
        big = max(range(len(s["blend"])), key=lambda i: abs(s["blend"][i][1]))
        s["blend"][big][1] = round(s["blend"][big][1] + (1.0 - total), 12)


def make_creature(c, name, description):
    body = body_particles(c)
    names = [n for n, _, _ in body]
    pos = [list(p) for _, p, _ in body]
    idx = {n: i for i, n in enumerate(names)}
    particles = [{"name": n, "position": list(p), "mass": m} for n, p, m in body]
    legs, feet = [], {}
    foot = {"rear": (-c["FOOT_X"], -c["FOOT_Y"]), "middle": (0.0, -c["MIDDLE_FOOT_Y"]),
            "front": (c["FOOT_X"], -c["FOOT_Y"])}
    for side, sign in (("right", 1.0), ("left", -1.0)):
        for part in ("rear", "middle", "front"):
            x, y = foot[part]
            feet[(side, part)] = len(particles)
            particles.append({"name": f"{side}_{part}_foot", "position": [x, sign * y, 0.0],
                              "mass": c["FOOT_MASS"]})
            pos.append([x, sign * y, 0.0])
            other = "left" if side == "right" else "right"
            legs.append({"name": f"{side}_{part}", "foot": feet[(side, part)], "side": side,
                         "mirror": f"{other}_{part}"})

    def body_spring(a, b):
        return {"name": f"{a}-{b}", "ends": [idx[a], idx[b]], "stiffness": c["BODY_K"],
                "damping": c["BODY_DAMPING"], "leg": None, "motor": False}

    springs = [body_spring(a, b) for a, b in BARS]
    polygons, skins = [], []
    for side, other in (("right", "left"), ("left", "right")):
        for part in ("rear", "middle", "front"):
            foot_i = feet[(side, part)]
            anchors = [idx[t.format(s=side, o=other)] for t in c["TIES"][part]]
            for b in anchors:
                springs.append({"name": f"{side}_{part}.{names[b]}", "ends": [b, foot_i],
                                "stiffness": c["LEG_K"], "damping": c["LEG_DAMPING"],
                                "leg": f"{side}_{part}", "motor": True})
            if c["SKIN"]:
                polygons += leg_skins(c, side, part, foot_i, pos, idx, skins, len(particles))
            else:
                for i in range(len(anchors)):
                    polygons.append({"vertices": [foot_i, anchors[i],
                                                  anchors[(i + 1) % len(anchors)]], "part": "leg"})
    for f in FACES:
        polygons.append({"vertices": [idx[v] for v in f], "part": "body"})
    fix_weight_sums(skins)
    creature = {"name": name, "description": description, "physics": c["PHYSICS"],
                "particles": particles, "legs": legs, "springs": springs, "polygons": polygons}
    if skins:
        creature["skin_vertices"] = skins
    assert len(particles) == 14 and len(springs) == 40
    return creature


def make_program(c):
    stride, lift = c["STRIDE"], c["LIFT"]
    positions = [
        ("swing", c["SWING_FORWARD"] * stride, 0.0, lift),
        ("down", stride / 2, 0.0, 0.0),
        ("back_1", stride / 4, 0.0, 0.0),
        ("back_2", 0.0, 0.0, 0.0),
        ("back_3", -stride / 4, 0.0, 0.0),
        ("back_4", -stride / 2, 0.0, 0.0),
    ]
    cycle = c["CYCLE"]
    slot = cycle / 6.0
    # Right side wave: rear, middle, front swing in slots 0, 1, 2; each leg then goes down and
    # steps back one notch per slot. The left side replays this half a cycle later.
    order = [p[0] for p in positions]
    instructions = []
    for k, part in enumerate(("rear", "middle", "front")):
        for j, position in enumerate(order):
            start = ((k + j) % 6) * slot - (c["SWING_LEAD"] * slot if position == "swing" else 0.0)
            instructions.append({"time": round(start % cycle, 6), "leg": f"right_{part}",
                                 "position": position})
    instructions.sort(key=lambda i: (i["time"], i["leg"]))
    return {
        "name": "metachronal wave",
        "description": "18 (time, leg, position) instructions for the right legs plus the loop at "
                       "cycle_period: 19 instructions. Left legs replay their mirror leg's "
                       "instructions mirror_time_offset later. Made by scripts/make_assets.py.",
        "cycle_period": cycle, "mirror_time_offset": cycle / 2, "gene_length_step": c["GENE_STEP"],
        "transition_time": c["TRANSITION"],
        "positions": [{"name": n, "foot_offset": [f, o, u]} for n, f, o, u in positions],
        "instructions": instructions,
    }


def apply_overrides(settings):
    """--set NAME=VALUE overrides a hexapod constant, --set wedge.NAME=VALUE a wedge one."""
    for item in settings:
        name, _, value = item.partition("=")
        target = HEXAPOD
        if name.startswith("wedge."):
            target, name = WEDGE, name[len("wedge."):]
        if name in target["PHYSICS"]:
            target["PHYSICS"][name] = float(value)
        elif name in target and name.isupper() and name not in ("TIES", "PHYSICS"):
            target[name] = float(value)
        else:
            raise SystemExit(f"make_assets.py: unknown parameter '{item.partition('=')[0]}'")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    parser.add_argument("--out", default=os.path.join(ROOT, "assets"), help="output folder")
    args = parser.parse_args()
    apply_overrides(args.set)
    files = {
        "hexapod.json": make_creature(
            HEXAPOD, "hexapod",
            "The default six-legged walker: 8 body particles, 6 splayed feet, 20 body and 20 leg "
            "springs, legs drawn as tapered limbs. Made by scripts/make_assets.py; see "
            "docs/model.md."),
        "metachronal.json": make_program(HEXAPOD),
        "wedge.json": make_creature(
            WEDGE, "wedge",
            "Nikovski's six-legged walker: 8 body particles, 6 feet, 20 body and 20 leg "
            "springs. Made by scripts/make_assets.py; see docs/model.md."),
        "wedge_metachronal.json": make_program(WEDGE),
    }
    for name, data in files.items():
        with open(os.path.join(args.out, name), "w") as out:
            json.dump(data, out, indent=1)
            out.write("\n")


if __name__ == "__main__":
    main()
