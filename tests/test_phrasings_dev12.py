"""The `unseen_dev12` templates (set O, held out for parser rounds 14 and 15, developed against in round 16): every
piece of the ground truth is written down.

Checked with small readers of their own (words for relations, comparators, readings, units, coordinates, order
cues) that share no code with the templates, over random subgoals drawn by hypothesis. Determinism:
tests/test_episodes_split.py.
"""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from template_checks import check_coordinates, check_goal, check_order, check_sensor
from test_phrasings_dev8 import _has, constraints, subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_dev12 as H
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# O's words for each relation, written here apart from the templates' own table
O_REL_WORDS = {"near": ("near", "steps from", "short way from"), "next_to": ("next to",),
               "beside": ("beside",), "by": ("by",), "on": ("on", "on top of"), "under": ("under", "underneath", "below"),
               "above": ("above",), "in": ("in", "inside", "stored in"), "with": ("with", "that has", "that have", "got"),
               "in_room_with": ("in the same room as", "in the room that has", "in the room containing"),
               "in_front_of": ("in front of",), "behind": ("behind", "round the back of"),
               "opposite": ("opposite", "facing"), "left_of": ("left of", "left-hand side of"),
               "right_of": ("right of", "right-hand side of")}


def test_split_is_wired():
    assert "unseen_dev12" in EPISODE_SPLITS and UNSEEN_TEMPLATES["unseen_dev12"] == ("phrasings_dev12", "dev12")
    assert _renderer("unseen_dev12", "goal") is H.render_goal_dev12
    assert _renderer("unseen_dev12", "sensor") is H.render_sensor_dev12
    assert _renderer("unseen_dev12", "hint") is H.hint_text_dev12
    assert _renderer("unseen_dev12", "instruction") is H.render_instruction_dev12


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = H.render_goal_dev12(np.random.default_rng(seed), sg)
    check_goal(text, sg, O_REL_WORDS, "{}")
    # the room is written before any relation, so it cannot be read as an anchor's
    if sg.room and sg.target.relations:
        first_anchor = min(text.rfind(r.anchor.phrase) for r in sg.target.relations)
        assert text.find(sg.room) < first_anchor, text


def test_anchor_relations_stay_in_brackets():
    t = Target("lamp", "lamp", (), (Relation("next_to", Target("credenza", "credenza", ("open",), (
        Relation("with", Target("record player", "record player")),))), Relation("under", Target("shelves", "shelves"))))
    rng = np.random.default_rng(0)
    for _ in range(40):
        text = H.render_goal_dev12(rng, Subgoal(0, t, room="music room"))
        at = text.index("(the one ")
        inner = text[at:text.index(")", at)]
        assert "record player" in inner and "shelves" not in inner and "open credenza (the one" in text, text


def _comparator(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"in the region of|round about|approximately|more or less", "approx"),
                  (r"at least|or above|no lower than|a minimum", "ge"),
                  (r"at most|at the most|or below|no higher than|not above|maximum", "le"),
                  (r"upwards of|above|more than|greater than|hotter than|warmer than|more humid than", "gt"),
                  (r"under|below|less than|lower than|cooler than|colder than|drier than", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def _reading(text: str) -> str:
    t = text.lower()
    if "ndvi" in t or re.search(r"health|green|lush|sickl", t):
        return "ndvi"
    if re.search(r"humid|damp|dri|mugg|%|percent", t):
        return "humidity_pct"
    if re.search(r"temperature|thermometer|warm|hot|cold|cool|chill|toast|°|degree|celsius|\bdeg\b", t):
        return "temperature_c"
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = H.render_sensor_dev12(np.random.default_rng(seed), c)
    check_sensor(rendered, c, _comparator, r"coldest|coolest|chilliest|least|sickliest|driest|lowest|bottom|poorest",
                 r"°|degree|celsius|\bdeg\b")
    assert _reading((rendered[0] + " " + rendered[1]).strip()) == c.reading, rendered


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = H.render_sensor_dev12(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = H.render_goal_dev12(rng, sg, prefix=prefix, tail=tail)
    assert _has(text, sg.target.head), text
    if prefix:  # a superlative adjective stands right before the noun phrase
        assert text.startswith(f"the {prefix} "), text
    else:
        core = tail.rstrip(",").split(" ", 1)[1]
        assert core in text and text.index(sg.target.head) < text.index(core), text


def test_number_formats_vary():
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(400):
        _, tail, _ = H.render_sensor_dev12(rng, SensorConstraint("temperature_c", "lt", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "decimal" if "-18.0" in tail else "digits")
    assert seen == {"words", "minus", "decimal", "digits"}


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(H.hint_text_dev12, H.render_goal_dev12, H.render_instruction_dev12, x, y, seed)


STRICT_CUES = r"by line no|line order|in the order given|only when it is done|thy final trial|in that order|" \
              r"stick to it|in exactly that order|in this order|one after the other|as listed"
FREE_CUES = r"any order|any sequence|picker's choice|whatever order|no order is decreed|pick the order|" \
            r"doesn't matter what order|order doesn't matter|choose the order myself"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(H.render_goal_dev12, H.render_instruction_dev12, sgs, seed, strict, STRICT_CUES, FREE_CUES)


def test_every_register_is_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [H.render_instruction_dev12(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    marks = ("ln  item|item:", "quest|relics|brave machine", "you have to|go and see|robot can you",
             "okay|got it|sure|confirming")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
