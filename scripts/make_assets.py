#!/usr/bin/env python3
"""Writes assets/hexapod.json and assets/metachronal.json from the parameters below.

The creature is data; this script is how that data was made, so every number in it can be
traced to a line here. Re-run it after changing a parameter: python3 scripts/make_assets.py
See docs/model.md for why each value is what it is.
"""
import argparse
import json
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

# --- Geometry (length unit: 1 = half the body length) -------------------------------------
BODY_X = 1.0          # belly corners and ridge ends at x = +-BODY_X
BODY_Y = 0.5          # belly corners at y = +-BODY_Y
BODY_BOTTOM = 0.6     # belly height when standing
BODY_TOP = 2.4        # ridge height (the ridge runs along the midline, y = 0)
FLANK_Y = 0.6         # flank particles at x = 0, y = +-FLANK_Y
FLANK_Z = 1.68        # and this height
FOOT_X = 1.4          # front and rear feet at x = +-FOOT_X
FOOT_Y = 0.35         # front and rear feet at y = -+FOOT_Y (right, left)
MIDDLE_FOOT_Y = 0.65  # middle feet at x = 0, y = -+MIDDLE_FOOT_Y

# --- Physical constants --------------------------------------------------------------------
BODY_MASS = 1.0       # per front body particle
REAR_MASS = 1.0       # per rear body particle (a heavy abdomen moves the centre of mass back)
FOOT_MASS = 0.2       # per foot particle
BODY_K = 600.0        # body truss spring stiffness
LEG_K = 25.0          # leg (motor) spring stiffness
BODY_ALPHA = 0.01     # damping = alpha * stiffness (time units); see docs/model.md
LEG_ALPHA = 0.1       # leg springs are damped more: their slow modes matter to the gait
PHYSICS = {
    "gravity": 0.2,
    "ground_stiffness": 400.0,
    "ground_damping": 8.0,
    "friction": 0.8,
    "slip_velocity": 0.02,
    "fall_height": 0.2,
    "fall_tilt_degrees": 45.0,
}

# --- Motor program -------------------------------------------------------------------------
CYCLE = 66.0          # time units per gait cycle (1000 time units ~ 15 cycles, as the paper)
STRIDE = 0.5          # foot travel relative to the body during stance
LIFT = 0.3            # swing height
GENE_STEP = 0.01      # rest-length change per gene unit
TRANSITION = 8.0      # time for a rest length to reach a new instruction's value
SWING_LEAD = 0.0      # a leg lifts this fraction of a slot before the previous leg lands
SWING_FORWARD = 0.3   # swing target's forward offset, as a fraction of the stride
# Leg positions, (name, forward, outward, up) foot offsets from the rest position; filled in
# by apply_overrides() from STRIDE, LIFT and SWING_FORWARD.
POSITIONS = []


def body_particles():
    """Belly corners, the ridge (on the mirror plane) and the two flanks, as (name, position)."""
    return [
        ("rear_belly_right", (-BODY_X, -BODY_Y, BODY_BOTTOM)),
        ("front_belly_right", (BODY_X, -BODY_Y, BODY_BOTTOM)),
        ("front_belly_left", (BODY_X, BODY_Y, BODY_BOTTOM)),
        ("rear_belly_left", (-BODY_X, BODY_Y, BODY_BOTTOM)),
        ("rear_ridge", (-BODY_X, 0.0, BODY_TOP)),
        ("front_ridge", (BODY_X, 0.0, BODY_TOP)),
        ("flank_right", (0.0, -FLANK_Y, FLANK_Z)),
        ("flank_left", (0.0, FLANK_Y, FLANK_Z)),
    ]


def apply_overrides(settings):
    """--set NAME=VALUE overrides a constant above (for parameter studies)."""
    g = globals()
    for item in settings:
        name, _, value = item.partition("=")
        if name in PHYSICS:
            PHYSICS[name] = float(value)
        elif name in g and name.isupper():
            g[name] = float(value)
        else:
            raise SystemExit(f"make_assets.py: unknown parameter '{name}'")
    g["POSITIONS"] = [
        ("swing", SWING_FORWARD * STRIDE, 0.0, LIFT),
        ("down", STRIDE / 2, 0.0, 0.0),
        ("back_1", STRIDE / 4, 0.0, 0.0),
        ("back_2", 0.0, 0.0, 0.0),
        ("back_3", -STRIDE / 4, 0.0, 0.0),
        ("back_4", -STRIDE / 2, 0.0, 0.0),
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    parser.add_argument("--out", default=os.path.join(ROOT, "assets"), help="output folder")
    args = parser.parse_args()
    apply_overrides(args.set)
    body = body_particles()
    names = [n for n, _ in body]
    pos = [p for _, p in body]
    idx = {n: i for i, n in enumerate(names)}
    particles = [{"name": n, "position": list(p), "mass": REAR_MASS if n.startswith("rear") else BODY_MASS}
                 for n, p in zip(names, pos)]
    legs, feet = [], {}
    foot = {"rear": (-FOOT_X, -FOOT_Y), "middle": (0.0, -MIDDLE_FOOT_Y), "front": (FOOT_X, -FOOT_Y)}
    for side, sign in (("right", 1.0), ("left", -1.0)):
        for part in ("rear", "middle", "front"):
            x, y = foot[part]
            feet[(side, part)] = len(particles)
            particles.append({"name": f"{side}_{part}_foot", "position": [x, sign * y, 0.0],
                              "mass": FOOT_MASS})
            other = "left" if side == "right" else "right"
            legs.append({"name": f"{side}_{part}", "foot": feet[(side, part)], "side": side,
                         "mirror": f"{other}_{part}"})

    def body_spring(a, b):
        return {"name": f"{a}-{b}", "ends": [idx[a], idx[b]], "stiffness": BODY_K,
                "damping": BODY_ALPHA * BODY_K, "leg": None, "motor": False}

    # The body truss: the edges of the carapace (belly rectangle, ridge, belly corners to the
    # ridge ends, flanks to their neighbours) plus the two belly diagonals and the bar between
    # the flanks. 20 bars, mirror-symmetric, rigidity rank 18 = 3 * 8 - 6 (checked by the tests).
    # A plain 8-corner box cannot be braced both rigidly and mirror-symmetrically with 20 bars:
    # every K4 on two mirror pairs is planar. Particles on the mirror plane (the ridge) avoid it.
    bars = [("rear_belly_right", "front_belly_right"), ("front_belly_right", "front_belly_left"),
            ("front_belly_left", "rear_belly_left"), ("rear_belly_left", "rear_belly_right"),
            ("rear_ridge", "front_ridge"),
            ("rear_belly_right", "rear_ridge"), ("rear_belly_left", "rear_ridge"),
            ("front_belly_right", "front_ridge"), ("front_belly_left", "front_ridge")]
    for side in ("right", "left"):
        for other in (f"rear_belly_{side}", f"front_belly_{side}", "rear_ridge", "front_ridge"):
            bars.append((f"flank_{side}", other))
    bars += [("rear_belly_right", "front_belly_left"), ("front_belly_right", "rear_belly_left"),
             ("flank_right", "flank_left")]
    springs = [body_spring(a, b) for a, b in bars]

    # Leg springs: front and rear feet tie to 3 body particles, middle feet to 4.
    # Chosen for well-conditioned tripods: the three (four) unit vectors from the body to the
    # foot span 3-D well (smallest singular value 0.33 front/rear, 0.49 middle), so a foot's
    # position relative to the body is firmly set by its springs' rest lengths.
    ties = {
        "rear": ["front_belly_{s}", "rear_belly_{o}", "rear_ridge"],
        "middle": ["flank_{s}", "flank_{o}", "front_belly_{o}", "rear_belly_{o}"],
        "front": ["rear_belly_{s}", "front_belly_{o}", "front_ridge"],
    }
    polygons = []
    for side, other in (("right", "left"), ("left", "right")):
        for part in ("rear", "middle", "front"):
            foot = feet[(side, part)]
            body = [idx[t.format(s=side, o=other)] for t in ties[part]]
            for b in body:
                springs.append({"name": f"{side}_{part}.{names[b]}", "ends": [b, foot],
                                "stiffness": LEG_K, "damping": LEG_ALPHA * LEG_K,
                                "leg": f"{side}_{part}", "motor": True})
            for i in range(len(body)):
                polygons.append({"vertices": [foot, body[i], body[(i + 1) % len(body)]], "part": "leg"})
    # Carapace faces, counter-clockwise seen from outside.
    faces = [["rear_belly_right", "rear_belly_left", "front_belly_left", "front_belly_right"],
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
    for f in faces:
        polygons.append({"vertices": [idx[v] for v in f], "part": "body"})

    creature = {
        "name": "hexapod",
        "description": "Nikovski's six-legged walker: 8 body particles, 6 feet, 20 body and 20 leg "
                       "springs. Made by scripts/make_assets.py; see docs/model.md.",
        "physics": PHYSICS, "particles": particles, "legs": legs, "springs": springs,
        "polygons": polygons,
    }
    assert len(particles) == 14 and len(springs) == 40

    slot = CYCLE / 6.0
    # Right side wave: rear, middle, front swing in slots 0, 1, 2; each leg then goes down and
    # steps back one notch per slot. The left side replays this half a cycle later.
    order = [p[0] for p in POSITIONS]
    instructions = []
    for k, part in enumerate(("rear", "middle", "front")):
        for j, position in enumerate(order):
            start = ((k + j) % 6) * slot - (SWING_LEAD * slot if position == "swing" else 0.0)
            instructions.append({"time": round(start % CYCLE, 6), "leg": f"right_{part}",
                                 "position": position})
    instructions.sort(key=lambda i: (i["time"], i["leg"]))
    program = {
        "name": "metachronal wave",
        "description": "18 (time, leg, position) instructions for the right legs plus the loop at "
                       "cycle_period: 19 instructions. Left legs replay their mirror leg's "
                       "instructions mirror_time_offset later. Made by scripts/make_assets.py.",
        "cycle_period": CYCLE, "mirror_time_offset": CYCLE / 2, "gene_length_step": GENE_STEP,
        "transition_time": TRANSITION,
        "positions": [{"name": n, "foot_offset": [f, o, u]} for n, f, o, u in POSITIONS],
        "instructions": instructions,
    }
    for name, data in (("hexapod.json", creature), ("metachronal.json", program)):
        with open(os.path.join(args.out, name), "w") as out:
            json.dump(data, out, indent=1)
            out.write("\n")


if __name__ == "__main__":
    main()
