"""The `unseen_dev10` templates (set M, held out for parser round 12, developed against in round 13): every piece of the ground truth is written down.

Checked with small readers of their own (words for comparators, numbers, units, coordinates, order cues) that
share no code with the templates, over random subgoals drawn by hypothesis. Determinism: tests/test_episodes_split.py.
"""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from template_checks import check_coordinates, check_goal, check_order, check_sensor
from test_phrasings_dev8 import constraints, subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_dev10 as H
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# M's words for each relation, written here apart from the templates' own table
M_REL_WORDS = {"near": ("near", "close to", "not far from", "around"), "next_to": ("next to", "adjacent to"),
               "beside": ("beside", "at the side of"), "by": ("by",), "on": ("on", "sitting on", "on top of"),
               "under": ("under", "beneath"), "above": ("above", "over"), "in": ("in", "inside"),
               "with": ("with", "that has", "that have"), "in_room_with": ("in the same room as", "in the room with"),
               "in_front_of": ("in front of",), "behind": ("behind", "at the back of"),
               "opposite": ("opposite", "across from"), "left_of": ("left of",), "right_of": ("right of",)}


def test_split_is_wired():
    assert "unseen_dev10" in EPISODE_SPLITS and UNSEEN_TEMPLATES["unseen_dev10"] == ("phrasings_dev10", "dev10")
    assert _renderer("unseen_dev10", "goal") is H.render_goal_dev10
    assert _renderer("unseen_dev10", "sensor") is H.render_sensor_dev10
    assert _renderer("unseen_dev10", "hint") is H.hint_text_dev10
    assert _renderer("unseen_dev10", "instruction") is H.render_instruction_dev10


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    check_goal(H.render_goal_dev10(np.random.default_rng(seed), sg), sg, M_REL_WORDS, "the {}")


def _comparator(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"roughly|approx\.|about", "approx"), (r"at least|no less than", "ge"), (r"no more than|at most", "le"),
                  (r"more than|above|over", "gt"), (r"less than|below|under", "lt")):
        if re.search(rx, t):
            return c
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    check_sensor(H.render_sensor_dev10(np.random.default_rng(seed), c), c, _comparator,
                 "lowest|coldest|coolest|least|sickest|driest", r"°c|degree|\bdeg\b|\d ?c\b")


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(H.hint_text_dev10, H.render_goal_dev10, H.render_instruction_dev10, x, y, seed, as_read=lambda t: t.replace("go 2 ", "go to "))


STRICT_CUES = r"in the order above|keep to this order|order as listed|\(in this order\)"
FREE_CUES = r"any order|doesn't matter what order|whatever order|order doesn't matter|\(any order\)"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(H.render_goal_dev10, H.render_instruction_dev10, sgs, seed, strict, STRICT_CUES, FREE_CUES)
