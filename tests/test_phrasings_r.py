"""The `unseen_r` held-out templates (set R): every piece of the ground truth is written down.

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

from ragnav_jax.language import phrasings_r as R
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# R's words for each relation, written here apart from the templates' own table
R_REL_WORDS = {"near": ("near", "short hop from", "no distance at all from", "short way from"),
               "next_to": ("next to", "cheek by jowl with", "shoulder to shoulder with"),
               "beside": ("beside",), "by": ("by",),
               "on": ("on",), "under": ("under",), "above": ("above",), "in": ("in", "inside"),
               "with": ("with", "accompanied by", "kept company by", "has", "have"),
               "in_room_with": ("same room as", "room that's home to", "room containing", "sharing four walls with"),
               "in_front_of": ("in front of",), "behind": ("behind",),
               "opposite": ("opposite", "across the way from", "face to face with"),
               "left_of": ("left of", "leftward of"), "right_of": ("right of", "rightward of")}


# ----------------------------------------------------------------------------------------------------
# Goals


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = R.render_goal_r(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, R_REL_WORDS)


def test_anchor_relations_stay_with_their_anchor():
    t = Target("lamp", "lamp", (), (Relation("next_to", Target("credenza", "credenza", ("open",), (
        Relation("with", Target("record player", "record player")),))), Relation("under", Target("shelves", "shelves"))))
    rng = np.random.default_rng(0)
    forms = set()
    for _ in range(80):
        text = R.render_goal_r(rng, Subgoal(0, t, room="music room"))
        dashes = re.search(r"the open credenza — the credenza that's (with|accompanied by|teamed with|kept company by) "
                           r"the record player — (and|and also|as well as) (\S+ ){0,2}under the shelves", text)
        commas = re.search(r"the open credenza, which has the record player with it, (and|and also|as well as) "
                           r"(\S+ ){0,2}under the shelves", text)
        assert dashes or commas, text  # not last: the anchor's clause is always closed
        forms.add("dashes" if dashes else "commas")
        assert text.index("music room") < text.index("credenza") < text.index("record player") < text.index("shelves")
    assert forms == {"dashes", "commas"}
    last = Target("lamp", "lamp", (), (Relation("near", Target("shelves", "shelves", (), (
        Relation("above", Target("desk", "desk")),))),))
    texts = [R.render_goal_r(rng, Subgoal(0, last)) for _ in range(60)]
    assert any(re.search(r"shelves, whose spot is (\S+ ){0,2}above the desk$", x) for x in texts)
    assert any(re.search(r"shelves — the shelves that are (\S+ ){0,2}above the desk$", x) for x in texts)


def test_states_and_attributes_take_every_form():
    rng = np.random.default_rng(2)
    t = Target("vintage corduroy bean bag", "bean bag", ("vintage", "corduroy", "empty"))
    texts = [R.render_goal_r(rng, Subgoal(0, t)) for _ in range(300)]
    for rx in (r"\(look for: vintage, corduroy\)", r"you'll know it, it's vintage and corduroy",
               r"such bean bag being vintage and corduroy", r"in its empty state", r"which you'll find empty",
               r"\(empty as we speak\)"):
        assert any(re.search(rx, x) for x in texts), rx
    one = Target("toy chest", "toy chest", ("open",))
    assert any(R.render_goal_r(rng, Subgoal(0, one)).startswith("the open toy chest") for _ in range(60))
    lamp = Target("lamp", "lamp", ("switched on",))
    assert any("the lamp in its switched-on state" in R.render_goal_r(rng, Subgoal(0, lamp)) for _ in range(60))
    plural = Target("teal shelves", "shelves", ("teal", "full"))
    texts = [R.render_goal_r(rng, Subgoal(0, plural)) for _ in range(100)]
    assert all("shelves in its" not in x and "know it, it's" not in x for x in texts)
    assert any("in their full state" in x for x in texts) and any("you'll know them, they're teal" in x for x in texts)
    rooms = {re.sub(r"^the kettle ", "", R.render_goal_r(rng, Subgoal(0, Target("kettle", "kettle"), room="pantry")))
             for _ in range(80)}
    assert rooms == {"in the pantry", "within the pantry", "along in the pantry", "situate in the pantry"}


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own


def _comparator(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"hovering|rough|pretty much|estimated|makes no odds", "approx"),
                  (r"dip below|meets or beats|or past it", "ge"),
                  (r"at or under|or under\b|limit of|doesn't break", "le"),
                  (r"cleared|tipped over|higher than|beats|outstrips", "gt"),
                  (r"made it to|comes in under|trails|lower than", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def _reading(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|green|perk", t):
        return "ndvi"
    if re.search(r"humid|damp|driest|%|percent|per cent", t):
        return "humidity_pct"
    if re.search(r"temp|warm|hot|cool|cold|°|degree|\d c\b", t):
        return "temperature_c"
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = R.render_sensor_r(np.random.default_rng(seed), c)
    check_sensor(rendered, c, _comparator, r"cool|cold|lowest|least|bottom|trails|driest", r"°|degree|\d c\b",
                 r"%|percent|per cent")
    assert _reading((rendered[0] + " " + rendered[1]).strip()) == c.reading, rendered


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = R.render_sensor_r(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = R.render_goal_r(rng, sg, prefix=prefix, tail=tail)
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
        _, tail, _ = R.render_sensor_r(rng, SensorConstraint("temperature_c", "lt", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "decimal" if "-18.0" in tail else "digits")
    assert seen == {"words", "minus", "decimal", "digits"}
    ndvi = {R.render_sensor_r(rng, SensorConstraint("ndvi", "gt", 0.6))[1] for _ in range(200)}
    assert any(re.search(r"(?<![\d])\.6\b", t) for t in ndvi) and any("0.60" in t for t in ndvi)
    assert all(read_numbers(t) == [pytest.approx(0.6)] for t in ndvi)
    hum = {R.render_sensor_r(rng, SensorConstraint("humidity_pct", "gt", 40.0))[1] for _ in range(200)}
    assert any("percent RH" in t for t in hum) and any("humidity-wise, " in t for t in hum)


def test_superlatives_take_adjectives_and_tails():
    rng = np.random.default_rng(5)
    got = {R.render_sensor_r(rng, SensorConstraint("ndvi", "max")) for _ in range(200)}
    prefixes = {p for p, _, _ in got if p}
    tails = {t for _, t, _ in got if t}
    assert {"healthiest", "greenest", "highest-NDVI", "perkiest"} <= prefixes
    assert {"that comes top on NDVI", "with the highest NDVI in the line-up", "that beats the rest on NDVI"} <= tails


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(R.hint_text_r, R.render_goal_r, R.render_instruction_r, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    neg = {R.hint_text_r(rng, "-3.5", "2.0") for _ in range(200)}
    for rx in (r"x co-ordinate -3\.5, y co-ordinate 2\.0", r"position ⟨-3\.5, 2\.0⟩", r"spot marked x -3\.5, y 2\.0"):
        assert any(re.search(rx, h) for h in neg), rx
    assert not any("metres along" in h or " E / " in h for h in neg)  # no 'east' or 'along' for a negative
    pos = {R.hint_text_r(rng, "3.5", "2.0") for _ in range(200)}
    for rx in (r"3\.5 metres along x and 2\.0 metres along y", r"plan position 3\.5 E / 2\.0 N"):
        assert any(re.search(rx, h) for h in pos), rx
    goal = R.render_goal_r(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="at position ⟨-3.5, 2.0⟩")
    assert goal.startswith("the guitar ") and "⟨-3.5, 2.0⟩" in goal


STRICT_CUES = r"fly the waypoints in sequence|in the sequence filed|sequence as filed|flown in that sequence|" \
              r"keep to this running order|nothing gets swapped|ascending order of designation|of the essence|" \
              r"in that order and not otherwise|in no other order|that exact order|same order i said|" \
              r"in that order, yeah"
FREE_CUES = r"pilot's discretion|however you like|slot in wherever|whichever you get to first|none of it moves|" \
            r"do them whenever|absolute discretion|shall not be material|order not material|any order whatsoever|" \
            r"any old order|order-wise i'm not bothered|mix and match"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(R.render_goal_r, R.render_instruction_r, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [R.render_goal_r(rng, sg) for sg in sgs]
    text = R.render_instruction_r(rng, res, "strict" if strict else "free")
    if strict:  # a strict text also says so in words of its own
        assert re.search(STRICT_CUES, text.lower()), text
    for r in res:  # every goal is written whole, after any false start
        assert r.lower() in text.lower(), (r, text)


def test_a_call_that_jumps_ahead_takes_it_back():
    rng = np.random.default_rng(6)
    res = ["the teal bean bag in the nursery", "the kettle", "the lamp over by the sofa"]
    taken_back = 0
    for _ in range(300):
        text = R.render_instruction_r(rng, res, "strict")
        m = re.search(r"(the [a-z ]+?) — no wait, hang on, (the [a-z ]+?) first, then (.*?)(?=, then |\. In that order)", text)
        if m:
            taken_back += 1
            said, first, then = m.groups()
            j = res.index(first)
            assert said == res[j + 1] and then.endswith(res[j + 1]), text
            assert "that exact order" in text.lower()
    assert taken_back > 5
    stammers = [R.render_instruction_r(rng, res, "free") for _ in range(200)]
    assert any("the te— the teal bean bag" in s for s in stammers)
    assert any("the teal — no, sorry — the teal bean bag" in s for s in stammers)


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = R.render_goal_r(rng, sg)
    text = R.render_instruction_r(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()), text


def test_every_register_is_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [R.render_instruction_r(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    marks = ("flight plan|callsign|cleared|wpt|tower to", "running order|wedding|planner|guests",
             "the robot shall|schedule|hereby agreed|“locations”", r"\[call transcript\]")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
    singles = [R.render_instruction_r(rng, res[:1], "strict") for _ in range(60)]
    for m in marks:
        assert any(re.search(m, t.lower()) for t in singles), m
