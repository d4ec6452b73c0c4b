"""The `unseen_dev10` templates (set M, held out for parser round 12, developed against in round 13): every piece of the ground truth is written down.

Checked with small readers of their own (words for comparators, numbers, units, coordinates, order cues) that
share no code with the templates, over random subgoals drawn by hypothesis. Determinism: tests/test_episodes_split.py.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import _all_targets, _has, constraints, read_numbers, subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_dev10 as H
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Location, Subgoal, Target

SETTINGS = settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
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
    text = H.render_goal_dev10(np.random.default_rng(seed), sg)
    plain = text.replace("-", " ")  # "switched-on" before a noun
    assert text.startswith("the ") and not text.endswith("-")
    for t in _all_targets(sg.target):
        assert _has(text, t.head), (t.head, text)
        for a in t.attributes:
            assert _has(text, a) or _has(plain, a), (a, text)
        for r in t.relations:
            assert any(_has(text, w) for w in M_REL_WORDS[r.type]), (r.type, text)
    if sg.room:
        assert _has(text, "the " + sg.room), text


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
    prefix, tail, written = H.render_sensor_dev10(np.random.default_rng(seed), c)
    text = (prefix + " " + tail).strip()
    assert bool(prefix) != bool(tail) and (written.reading, written.comparator) == (c.reading, c.comparator)
    if c.is_superlative:
        low = "lowest|coldest|coolest|least|sickest|driest"
        assert written.value is None and read_numbers(text) == [], text
        assert bool(re.search(low, text)) == (c.comparator == "min"), text
        return
    assert written.value == pytest.approx(c.value, abs=0.006)
    assert read_numbers(text.replace("°C", " C")) == [pytest.approx(written.value)], text
    assert _comparator(text) == c.comparator, text
    unit = "c" if re.search(r"°c|degree|\bdeg\b|\d ?c\b", text.lower()) else "%" if re.search(r"%|percent", text) else ""
    assert unit == written.unit, text


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    xs, ys = (f"{v:.1f}" for v in (x + 0.0, y + 0.0))
    rng = np.random.default_rng(seed)
    hint = H.hint_text_dev10(rng, xs, ys)
    assert [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", hint)] == [float(xs), float(ys)], hint
    goal = H.render_goal_dev10(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(x, y)), hint=hint)
    text = H.render_instruction_dev10(rng, [goal], "strict").replace("go 2 ", "go to ")  # the text's "2" for "to"
    assert [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)] == [float(xs), float(ys)], text


STRICT_CUES = r"in the order above|keep to this order|order as listed|\(in this order\)"
FREE_CUES = r"any order|doesn't matter what order|whatever order|order doesn't matter|\(any order\)"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [H.render_goal_dev10(rng, sg) for sg in sgs]
    order = "strict" if strict else "free"
    low = H.render_instruction_dev10(rng, res, order).lower()
    assert not re.search(FREE_CUES, low) if strict else re.search(FREE_CUES, low), low
    if not strict:
        assert not re.search(STRICT_CUES, low), low
    at = 0
    for sg in sgs:  # every goal's head, in visiting order
        at = low.find(sg.target.head, at)
        assert at >= 0, (sg.target.head, low)
