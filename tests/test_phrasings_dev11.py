"""The `unseen_dev11` templates (set N, held out for parser round 13, developed against in round 14): every piece of the ground truth is written down.

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
from ragnav_jax.language import phrasings_dev11 as H
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# N's words for each relation, written here apart from the templates' own table
N_REL_WORDS = {"near": ("near", "nr", "close of", "close to"), "next_to": ("next to", "nxt to"),
               "beside": ("beside",), "by": ("by",), "on": ("on", "on the top of", "on top of"), "under": ("under", "below"),
               "above": ("above", "over"), "in": ("in", "inside of"), "with": ("with", "w/"),
               "in_room_with": ("in the same room as", "in same room as"), "in_front_of": ("in front of",),
               "behind": ("behind",), "opposite": ("opposite",), "left_of": ("left of",), "right_of": ("right of",)}


def test_split_is_wired():
    assert "unseen_dev11" in EPISODE_SPLITS and UNSEEN_TEMPLATES["unseen_dev11"] == ("phrasings_dev11", "dev11")
    assert _renderer("unseen_dev11", "goal") is H.render_goal_dev11
    assert _renderer("unseen_dev11", "sensor") is H.render_sensor_dev11
    assert _renderer("unseen_dev11", "hint") is H.hint_text_dev11
    assert _renderer("unseen_dev11", "instruction") is H.render_instruction_dev11


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    check_goal(H.render_goal_dev11(np.random.default_rng(seed), sg), sg, N_REL_WORDS, "{}")


def _comparator(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"approx|around|about", "approx"), (r"minimum|not less than", "ge"), (r"not more than|maximum", "le"),
                  (r"more than|bigger than|higher than", "gt"), (r"less than|lower than|smaller than", "lt")):
        if re.search(rx, t):
            return c
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    check_sensor(H.render_sensor_dev11(np.random.default_rng(seed), c), c, _comparator,
                 r"lowest|coldest|coolest|least|unhealthiest|driest|\bmin\b", r"°|degree|\bdeg\b|\d ?c\b")


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(H.hint_text_dev11, H.render_goal_dev11, H.render_instruction_dev11, x, y, seed)


STRICT_CUES = r"in that order|\(in order\)|^first:|after go to|after you go|then you go"
FREE_CUES = r"any order|order not important|whichever order|order is not important|order you can choose"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(H.render_goal_dev11, H.render_instruction_dev11, sgs, seed, strict, STRICT_CUES, FREE_CUES)
