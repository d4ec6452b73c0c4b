"""The `unseen_s` held-out templates (set S): every piece of the ground truth is written down.

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

from ragnav_jax.language import phrasings_s as S
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# S's words for each relation, written here apart from the templates' own table
S_REL_WORDS = {"near": ("near", "stride or two from", "arm's length of", "million miles from"),
               "next_to": ("next to", "next door to", "elbow to elbow with"),
               "beside": ("beside",), "by": ("by",),
               "on": ("on",), "under": ("under", "beneath"), "above": ("above",), "in": ("in", "inside"),
               "with": ("with", "sporting", "boasting", "carries", "carry", "has", "have"),
               "in_room_with": ("same room as", "room occupied by", "whatever room holds"),
               "in_front_of": ("in front of",), "behind": ("behind",),
               "opposite": ("opposite", "face-on to"),
               "left_of": ("left of",), "right_of": ("right of",)}


# ----------------------------------------------------------------------------------------------------
# Goals


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = S.render_goal_s(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, S_REL_WORDS)


def test_anchor_relations_stay_with_their_anchor():
    t = Target("lamp", "lamp", (), (Relation("next_to", Target("credenza", "credenza", ("open",), (
        Relation("with", Target("record player", "record player")),))), Relation("under", Target("shelves", "shelves"))))
    rng = np.random.default_rng(0)
    forms = set()
    for _ in range(80):
        text = S.render_goal_s(rng, Subgoal(0, t, room="music room"))
        brackets = re.search(r"the open credenza \(you'll find it (with|sporting) the record player\),? "
                             r"(and|and also) (\S+ ){0,2}(under|beneath) the shelves", text)
        commas = re.search(r"the open credenza, which incidentally has the record player, (and|and also) "
                           r"(\S+ ){0,2}(under|beneath) the shelves", text)
        assert brackets or commas, text  # not last: the anchor's clause is always closed
        forms.add("brackets" if brackets else "commas")
        assert text.index("music room") < text.index("credenza") < text.index("record player") < text.index("shelves")
    assert forms == {"brackets", "commas"}
    last = Target("lamp", "lamp", (), (Relation("near", Target("shelves", "shelves", (), (
        Relation("above", Target("desk", "desk")),))),))
    texts = [S.render_goal_s(rng, Subgoal(0, last)) for _ in range(60)]
    assert any(re.search(r"shelves, which incidentally are (\S+ ){0,2}above the desk$", x) for x in texts)
    assert any(re.search(r"shelves \(you'll find them (\S+ ){0,2}above the desk\)$", x) for x in texts)


def test_states_and_attributes_take_every_form():
    rng = np.random.default_rng(2)
    t = Target("vintage corduroy bean bag", "bean bag", ("vintage", "corduroy", "empty"))
    texts = [S.render_goal_s(rng, Subgoal(0, t)) for _ in range(300)]
    for rx in (r"^the vintage corduroy bean bag", r"\(think vintage and corduroy\)", r"matching “vintage, corduroy”",
               r", left empty", r"\(as found: empty\)", r", showing as empty"):
        assert any(re.search(rx, x) for x in texts), rx
    one = Target("toy chest", "toy chest", ("open",))
    assert any(S.render_goal_s(rng, Subgoal(0, one)).startswith("the open toy chest") for _ in range(60))
    lamp = Target("lamp", "lamp", ("switched on",))
    assert any(S.render_goal_s(rng, Subgoal(0, lamp)) == "the switched-on lamp" for _ in range(60))
    plural = Target("teal shelves", "shelves", ("teal",), (Relation("with", Target("drums", "drums")),))
    texts = [S.render_goal_s(rng, Subgoal(0, plural)) for _ in range(100)]
    assert all("shelves that carries" not in x for x in texts) and any("that carry the drums" in x for x in texts)
    rooms = {re.sub(r"^the kettle ", "", S.render_goal_s(rng, Subgoal(0, Target("kettle", "kettle"), room="pantry")))
             for _ in range(80)}
    assert rooms == {"in the pantry", "in the pantry area", "(zone: pantry)"}


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own


def _comparator(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"whisker|pretty close|somewhere about", "approx"),
                  (r"or higher|or beyond|as its floor", "ge"),
                  (r"or lower|maxes out|maxing out|upper bound", "le"),
                  (r"clocking in above|edging over|edged past|betters", "gt"),
                  (r"dipping under|running below|cracked|undershoots", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def _reading(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|flourish|robust|ailing|feeble", t):
        return "ndvi"
    if re.search(r"humid|steam|%|percent|arid|dri", t):
        return "humidity_pct"
    if re.search(r"temp|warm|swelter|hot|cold|frigid|nipp|°|degree|degs|celsius", t):
        return "temperature_c"
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = S.render_sensor_s(np.random.default_rng(seed), c)
    check_sensor(rendered, c, _comparator, r"cold|frigid|nipp|least|ailing|feeble|arid|dri|lowest|last",
                 r"°|degree|degs|celsius", r"%|percent")
    assert _reading((rendered[0] + " " + rendered[1]).strip()) == c.reading, rendered


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = S.render_sensor_s(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = S.render_goal_s(rng, sg, prefix=prefix, tail=tail)
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
        _, tail, _ = S.render_sensor_s(rng, SensorConstraint("temperature_c", "lt", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "decimal" if "-18.0" in tail else "digits")
    assert seen == {"words", "minus", "decimal", "digits"}
    ndvi = {S.render_sensor_s(rng, SensorConstraint("ndvi", "gt", 0.6))[1] for _ in range(200)}
    assert any(re.search(r"(?<![\d])\.6\b", t) for t in ndvi) and any("0.60" in t for t in ndvi)
    assert all(read_numbers(t) == [pytest.approx(0.6)] for t in ndvi)
    assert any(t.endswith(" on NDVI") for t in ndvi) and any(t.startswith("with an NDVI score ") for t in ndvi)
    hum = {S.render_sensor_s(rng, SensorConstraint("humidity_pct", "gt", 40.0))[1] for _ in range(200)}
    assert any("% relative humidity" in t for t in hum) and any("percent humidity" in t for t in hum)
    temp = {S.render_sensor_s(rng, SensorConstraint("temperature_c", "approx", 21.0))[1] for _ in range(200)}
    assert any("degs" in t for t in temp) and any(t.startswith("whose temp's ") for t in temp)


def test_superlatives_take_adjectives_and_tails():
    rng = np.random.default_rng(5)
    got = {S.render_sensor_s(rng, SensorConstraint("temperature_c", "min")) for _ in range(200)}
    prefixes = {p for p, _, _ in got if p}
    tails = {t for _, t, _ in got if t}
    assert {"coldest", "most frigid", "nippiest"} <= prefixes
    assert {"that comes last on temperature", "with the lowest temp of any", "whose temperature sits lowest"} <= tails


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(S.hint_text_s, S.render_goal_s, S.render_instruction_s, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {S.hint_text_s(rng, "-3.5", "2.0") for _ in range(200)}
    for rx in (r"x-line -3\.5 crosses the y-line 2\.0", r"grid reference -3\.5 × 2\.0", r"\(x → -3\.5, y → 2\.0\)",
               r"intersection of x = -3\.5 and y = 2\.0", r"first coordinate -3\.5, second coordinate 2\.0"):
        assert any(re.search(rx, h) for h in hints), rx
    goal = S.render_goal_s(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="(x → -3.5, y → 2.0)")
    assert goal == "the guitar (x → -3.5, y → 2.0)"


STRICT_CUES = r"solve the clues in order|clue by clue|one-way system|stick to that sequence|one way only|" \
              r"junctions in number order|\[x\] as listed|mandatory|in field order|line course|controls in order|" \
              r"order shown"
FREE_CUES = r"scramble, not a trail|no trail to follow|any order you like|pick your own route|any running order|" \
            r"\[x\] at the robot's discretion|not prescribed|no fixed order|score event|any sequence you choose|" \
            r"plan your own route"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(S.render_goal_s, S.render_instruction_s, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [S.render_goal_s(rng, sg) for sg in sgs]
    text = S.render_instruction_s(rng, res, "strict" if strict else "free")
    if strict:  # a strict text also says so in words of its own
        assert re.search(STRICT_CUES, text.lower()), text
    for r in res:  # every goal is written whole
        assert r.lower() in text.lower(), (r, text)


def test_tick_boxes_say_which_order():
    rng = np.random.default_rng(7)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    strict = [S.render_instruction_s(rng, res, "strict") for _ in range(200)]
    free = [S.render_instruction_s(rng, res, "free") for _ in range(200)]
    assert any("[X] as listed in Section A   [ ] at the robot's discretion" in t for t in strict)
    assert any("[ ] as listed in Section A   [X] at the robot's discretion" in t for t in free)
    assert not any("[X] at the robot's discretion" in t for t in strict)
    assert not any("[X] as listed" in t for t in free)


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = S.render_goal_s(rng, sg)
    text = S.render_instruction_s(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()), text


def test_every_register_is_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [S.render_instruction_s(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    marks = ("treasure", "travel", r"form ra|request for robot attendance|application for household",
             "orienteering|control|patrol")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
    singles = [S.render_instruction_s(rng, res[:1], "strict") for _ in range(60)]
    for m in marks:
        assert any(re.search(m, t.lower()) for t in singles), m
