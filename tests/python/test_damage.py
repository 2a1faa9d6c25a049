"""A damaged creature from Python (hexgait.Creature(damage=...)): the same bits as
`hexgait simulate --damage`, on the scalar and batched paths, and the command line's messages."""
import json
import os
import subprocess

import numpy as np
import pytest

import hexgait

HEXGAIT = os.environ["HEXGAIT_BIN"]
DAMAGE = "right_front:weak=0.2,left_rear:locked,right_middle:short=0.8,left_front:lost"


def test_damaged_creature_runs_as_the_command_line_does():
    done = subprocess.run([HEXGAIT, "simulate", "--json", "--unoptimized", "--damage", DAMAGE],
                          capture_output=True, text=True, check=True)
    reference = json.loads(done.stdout)
    assert reference["damage"] == DAMAGE
    creature = hexgait.Creature("hexapod", damage=DAMAGE)
    assert creature.damage == DAMAGE
    assert "damage='" + DAMAGE + "'" in repr(creature)
    run = hexgait.simulate(creature=creature)
    batch = hexgait.Evaluator(creature=creature).evaluate(np.zeros((3, 120), np.int8))
    assert run["distance"] == reference["distance"]  # bit for bit
    assert batch["distance"].tolist() == [reference["distance"]] * 3
    intact = hexgait.simulate()
    assert intact["distance"] != reference["distance"]


def test_bad_damage_is_a_value_error_with_the_command_lines_message():
    with pytest.raises(ValueError, match="unknown leg 'right_fornt'"):
        hexgait.Creature(damage="right_fornt:weak=0.2")
    with pytest.raises(ValueError, match=r"factor 2 is outside \[0.01, 1\] for weak"):
        hexgait.Creature(damage="right_front:weak=2")
    with pytest.raises(ValueError, match="lost takes no factor"):
        hexgait.Creature(damage="right_front:lost=0.5")
