"""The `unseen_q` held-out templates (set Q): every piece of the ground truth is written down.

Checked with small readers of their own (words for relations, comparators, readings, units, coordinates, order
cues) that share no code with the templates, over random subgoals drawn by hypothesis. Whole generated episode files
are checked for determinism here; the split's wiring and the four functions' determinism in tests/test_heldout_sets.py.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from template_checks import check_coordinates, check_goal_layout, check_order, check_sensor
from test_phrasings_dev8 import _has, constraints, read_numbers, subgoals

from ragnav_jax.language import phrasings_q as Q
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# Q's words for each relation, written here apart from the templates' own table
Q_REL_WORDS = {"near": ("near", "few paces of", "couple of steps from", "not far from", "close to"),
               "next_to": ("next to", "adjoining", "alongside"), "beside": ("beside",), "by": ("by",),
               "on": ("on", "upon"), "under": ("under", "underneath", "beneath", "below"),
               "above": ("above", "up over"), "in": ("in", "inside", "held in"),
               "with": ("with", "paired with", "together with", "has", "have"),
               "in_room_with": ("same room as", "sharing a room with", "room housing"),
               "in_front_of": ("in front of",), "behind": ("behind",),
               "opposite": ("opposite", "facing", "across from"), "left_of": ("left of", "left side of"),
               "right_of": ("right of", "right side of")}


# ----------------------------------------------------------------------------------------------------
# Goals


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = Q.render_goal_q(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, Q_REL_WORDS, (",", ";"))


def test_anchor_relations_stay_in_their_clause():
    t = Target("lamp", "lamp", (), (Relation("next_to", Target("credenza", "credenza", ("open",), (
        Relation("with", Target("record player", "record player")),))), Relation("under", Target("shelves", "shelves"))))
    rng = np.random.default_rng(0)
    for _ in range(60):
        text = Q.render_goal_q(rng, Subgoal(0, t, room="music room"))
        assert "the open credenza (which in turn " in text, text  # not last: always closed by a bracket
        assert re.search(r"\((which in turn (has|comes with|is paired with) the record player)\)", text), text
        assert text.index("music room") < text.index("credenza") < text.index("record player") < text.index("shelves")
    last = Target("lamp", "lamp", (), (Relation("near", Target("shelves", "shelves", (), (
        Relation("above", Target("desk", "desk")),))),))
    forms = {bool(re.search(r"shelves, which in turn are \S+", Q.render_goal_q(rng, Subgoal(0, last))))
             for _ in range(60)}
    assert forms == {True, False}  # a closing anchor takes the comma form now and then, plural verb 'are'


def test_states_and_attributes_take_every_form():
    rng = np.random.default_rng(2)
    t = Target("vintage corduroy bean bag", "bean bag", ("vintage", "corduroy", "empty"))
    texts = [Q.render_goal_q(rng, Subgoal(0, t)) for _ in range(300)]
    for rx in (r"\(vintage/corduroy\)", r"described as vintage and corduroy", r"of the vintage, corduroy (variety|kind|sort)",
               r"presently empty", r"which was empty when I last looked", r"\(empty at the time of writing\)"):
        assert any(re.search(rx, x) for x in texts), rx
    one = Target("toy chest", "toy chest", ("open",))
    assert any(Q.render_goal_q(rng, Subgoal(0, one)).startswith("the open toy chest") for _ in range(60))
    plural = Target("shelves", "shelves", ("full",))
    assert all("shelves, which was" not in Q.render_goal_q(rng, Subgoal(0, plural)) for _ in range(60))


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own


def _comparator(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"something like|on or about|plus or minus|near enough", "approx"),
                  (r"or upward|at the very least|bottoming out", "ge"),
                  (r"at the outside|as its ceiling|doesn't go beyond|topping out", "le"),
                  (r"\bover\b|above|higher than|warmer than|more humid than", "gt"),
                  (r"\bunder\b|shy of|beneath|hasn't climbed|cooler than|drier than", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def _reading(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|green|thriv|wilt|droop", t):
        return "ndvi"
    if re.search(r"humid|damp|sogg|moist|dri|parch|%|percent|per cent", t):
        return "humidity_pct"
    if re.search(r"temp|warm|hot|balm|cold|cool|frost|iciest|°|degree|\d c\b", t):
        return "temperature_c"
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = Q.render_sensor_q(np.random.default_rng(seed), c)
    check_sensor(rendered, c, _comparator, r"cold|cool|frost|iciest|least|wilt|droop|driest|parch|lowest|bottom",
                 r"°|degree|\d c\b", r"%|percent|per cent")
    assert _reading((rendered[0] + " " + rendered[1]).strip()) == c.reading, rendered


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = Q.render_sensor_q(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = Q.render_goal_q(rng, sg, prefix=prefix, tail=tail)
    assert _has(text, sg.target.head), text
    if sg.room:
        assert _has(text, sg.room), text
    if prefix:  # a superlative adjective stands right before the noun phrase
        assert text.startswith(f"the {prefix} "), text
    else:
        core = tail.split(" ", 1)[1]
        assert core in text and text.index(sg.target.head) < text.index(core), text


def test_number_formats_vary():
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(400):
        _, tail, _ = Q.render_sensor_q(rng, SensorConstraint("temperature_c", "lt", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "decimal" if "-18.0" in tail else "digits")
    assert seen == {"words", "minus", "decimal", "digits"}
    ndvi = {Q.render_sensor_q(rng, SensorConstraint("ndvi", "gt", 0.6))[1] for _ in range(200)}
    assert any(re.search(r"(?<![\d])\.6\b", t) for t in ndvi) and any("0.60" in t for t in ndvi)
    assert all(read_numbers(t) == [pytest.approx(0.6)] for t in ndvi)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(Q.hint_text_q, Q.render_goal_q, Q.render_instruction_q, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {Q.hint_text_q(rng, "-3.5", "2.0") for _ in range(200)}
    for rx in (r"x reads -3\.5 and y reads 2\.0", r"-3\.5 on the x-axis and 2\.0 on the y-axis", r"waypoint -3\.5 \| 2\.0",
               r"map reference -3\.5, 2\.0", r"x-value -3\.5, y-value 2\.0"):
        assert any(re.search(rx, h) for h in hints), rx
    goal = Q.render_goal_q(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="at waypoint -3.5 | 2.0")
    assert goal.startswith("the guitar ") and "-3.5 | 2.0" in goal


STRICT_CUES = r"in the order given|no deviation|that sequence and no other|not to be changed|steps in order|" \
              r"don't skip ahead|order matters|exactly as written|strict sequence|don't change the sequence|" \
              r"numbered sequence|keep to the order of the tour|alphabetical order|retrace it exactly|" \
              r"same order as the statement|exactly that order|part of the evidence"
FREE_CUES = r"navigator's choice|whatever order the wind|no consequence|in any order|whatever order you fancy|" \
            r"no method to follow|comes out the same|self-guided|free-roaming|no fixed route|" \
            r"whatever order catches|sequence immaterial|neither here nor there|whatever order your instincts"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(Q.render_goal_q, Q.render_instruction_q, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    if strict:  # a strict text also says so in words of its own
        rng = np.random.default_rng(seed)
        res = [Q.render_goal_q(rng, sg) for sg in sgs]
        assert re.search(STRICT_CUES, Q.render_instruction_q(rng, res, "strict").lower())


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = Q.render_goal_q(rng, sg)
    text = Q.render_instruction_q(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()), text


def test_every_register_is_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [Q.render_instruction_q(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    marks = ("captain|helm|heading|ports of call", "method|step 1|ingredients|recipe",
             "tour|track 1|exhibits|audio guide|stop a:", "case notes|suspect|inspector|clues")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
