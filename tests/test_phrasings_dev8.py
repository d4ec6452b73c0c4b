"""The `unseen_dev8` templates (set D, held out until parser round 9): deterministic, and every piece of the ground truth is written down.

Checked with small readers of their own (numbers, units, comparators, coordinates, order words) that share no
code with the templates, over random subgoals drawn by hypothesis.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_dev8 as H
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import RELATION_TYPES, Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

HEADS = ("lamp", "sofa", "hi-fi speaker", "night-light", "mini-fridge", "ping-pong table", "shelves", "drums",
         "chest freezer", "snake plant", "toolbox", "cactus", "appliance", "tool chest")
MODS = ("teal", "burgundy", "lacquered", "vintage", "wool", "glazed", "king-size", "gold-framed", "olive")
STATES = ("switched on", "switched off", "open", "closed", "empty", "full")
ROOMS = ("kitchen", "games room", "laundry room", "nursery", "living room", "music room")
# each relation type and the words that say it (a reader's list, not the templates')
REL_WORDS = {
    "near": ("near", "close to", "not far from"), "next_to": ("next to", "alongside"), "beside": ("beside",),
    "by": ("by",), "on": ("on",), "under": ("under", "underneath", "beneath"), "above": ("above",), "in": ("in", "inside"),
    "with": ("with", "has", "have"), "in_room_with": ("same room as", "room with"), "in_front_of": ("in front of",),
    "behind": ("behind",), "opposite": ("opposite", "across from", "facing"), "left_of": ("left of",),
    "right_of": ("right of",),
}


@st.composite
def targets(draw, depth: int = 2):
    head = draw(st.sampled_from(HEADS))
    mods = draw(st.lists(st.sampled_from(MODS), max_size=2, unique=True))
    states = draw(st.lists(st.sampled_from(STATES), max_size=1))
    rels = ()
    if depth > 0:
        n = draw(st.integers(0, 2 if depth == 2 else 1))
        rels = tuple(Relation(draw(st.sampled_from(RELATION_TYPES)), draw(targets(depth=depth - 1))) for _ in range(n))
    return Target(" ".join((*mods, head)), head, tuple(mods) + tuple(states), rels)


@st.composite
def subgoals(draw):
    t = draw(targets())
    room = draw(st.none() | st.sampled_from(ROOMS))
    return Subgoal(0, t, room=room)


def _words(text: str) -> str:
    return " " + re.sub(r"[^a-z0-9\-'.%°]+", " ", text.lower()) + " "


def _has(text: str, phrase: str) -> bool:
    return f" {phrase.lower()} " in _words(text)


def _all_targets(t: Target):
    yield t
    for r in t.relations:
        yield from _all_targets(r.anchor)


# ----------------------------------------------------------------------------------------------------
# Determinism and wiring


def test_split_is_wired():
    assert "unseen_dev8" in EPISODE_SPLITS
    assert UNSEEN_TEMPLATES["unseen_dev8"] == ("phrasings_dev8", "dev8")
    assert _renderer("unseen_dev8", "goal") is H.render_goal_dev8
    assert _renderer("unseen_dev8", "sensor") is H.render_sensor_dev8
    assert _renderer("unseen_dev8", "hint") is H.hint_text_dev8
    assert _renderer("unseen_dev8", "instruction") is H.render_instruction_dev8


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_same_seed_same_text(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [H.render_goal_dev8(rng, sg, hint=H.hint_text_dev8(rng, "3.5", "2")) for sg in sgs]
        extra = H.render_sensor_dev8(rng, SensorConstraint("temperature_c", "ge", 20.0))
        return res, extra, H.render_instruction_dev8(rng, res, "strict" if strict else "free")

    assert run() == run()


# ----------------------------------------------------------------------------------------------------
# Goals: every head, attribute, room and anchor is written, anchors after what they anchor


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = H.render_goal_dev8(np.random.default_rng(seed), sg)
    assert text.startswith("the ")
    for t in _all_targets(sg.target):
        assert _has(text, t.head), (t.head, text)
        for a in t.attributes:
            assert _has(text, a), (a, text)
        for r in t.relations:
            assert any(_has(text, w) for w in REL_WORDS[r.type]), (r.type, text)
    if sg.room:
        assert _has(text, sg.room) or _has(text, sg.room + "'s"), text
    # the goal's own head comes first; an anchor is written after the noun it anchors
    low = text.lower()
    assert low.find(sg.target.head) <= min((low.find(r.anchor.head) for r in sg.target.relations), default=10**6) or \
        any(sg.target.head in r.anchor.head for r in sg.target.relations)
    # the room is written before any relation, so it cannot attach to an anchor
    if sg.room and sg.target.relations:
        first_anchor = min(low.rfind(r.anchor.phrase) for r in sg.target.relations)
        assert low.find(sg.room) < first_anchor or sg.room in " ".join(t.phrase for t in _all_targets(sg.target))


def test_states_and_plurals_read_naturally():
    rng = np.random.default_rng(0)
    t = Target("shelves", "shelves", ("open",), (Relation("near", Target("drums", "drums", (), (
        Relation("next_to", Target("teal hi-fi speaker", "hi-fi speaker", ("teal", "switched on"))),))),))
    for _ in range(40):
        text = H.render_goal_dev8(rng, Subgoal(0, t, room="music room"))
        assert "drums which is" not in text and "drums that is" not in text and "shelves that's" not in text
        assert "teal hi-fi speaker (switched on)" in text  # a state after a modified anchor goes in brackets


def test_split_attributes_reads_the_phrase():
    t = Target("teal tumble dryer", "tumble dryer", ("teal", "switched on"))
    assert H.split_attributes(t) == (["teal"], ["switched on"])
    assert H.split_attributes(Target("toy chest", "toy chest", ("open",))) == ([], ["open"])


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_UNITS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9,
          "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16,
          "seventeen": 17, "eighteen": 18, "nineteen": 19, "zero": 0}
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80,
         "ninety": 90}


def read_numbers(text: str) -> list[float]:
    """Every number written in the text: digits ('-18', '.35', '20.0') or words ('minus twenty-two')."""
    out = []
    toks = re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)?", text.lower())
    neg = False
    for tok in toks:
        if tok == "minus":
            neg = True
            continue
        val = None
        if re.fullmatch(r"-?\d*\.?\d+", tok):
            val = float(tok)
        else:
            parts = tok.split("-")
            if all(p in _UNITS or p in _TENS for p in parts):
                val = float(sum(_UNITS.get(p, 0) + _TENS.get(p, 0) for p in parts))
        if val is not None:
            out.append(-val if neg else val)
        neg = False
    return out


def read_unit(text: str) -> str:
    t = text.lower()
    if re.search(r"°c|degree|\bdeg\b|\d c\b| c\b", t):
        return "c"
    if "%" in t or "percent" in t or "per cent" in t:
        return "%"
    return ""


def read_comparator(text: str) -> str:
    t = " " + text.lower() + " "
    if re.search(r"\b(about|around|roughly|approximately|give or take)\b", t):
        return "approx"
    if re.search(r"\bor (more|higher|warmer)\b|at least|no (cooler|drier|lower) than", t):
        return "ge"
    if re.search(r"\bor (less|lower|colder)\b|at most|no (warmer|more humid|higher) than", t):
        return "le"
    if re.search(r"\b(warmer|hotter|more humid|higher|more|greater) than\b|\b(over|above)\b", t):
        return "gt"
    if re.search(r"\b(colder|cooler|drier|less humid|lower|less) than\b|\b(under|below)\b", t):
        return "lt"
    return "?"


def read_reading(text: str) -> str:
    t = text.lower()
    if "ndvi" in t or "health" in t or "lush" in t or "sickl" in t:
        return "ndvi"
    if "humid" in t or "damp" in t or "dri" in t or "%" in t or "percent" in t or "per cent" in t:
        return "humidity_pct"
    return "temperature_c"


def read_superlative(text: str) -> str:
    t = text.lower()
    if re.search(r"coldest|chilliest|lowest|least|sickliest|driest|worst", t):
        return "min"
    if re.search(r"warmest|hottest|highest|healthiest|lushest|most humid|dampest|best", t):
        return "max"
    return "?"


_VALUES = {"temperature_c": st.integers(-30, 400).map(float) | st.sampled_from([20.5, -2.5, 37.5]),
           "ndvi": st.integers(1, 19).map(lambda k: round(k * 0.05, 2)),
           "humidity_pct": st.integers(5, 95).map(float)}


@st.composite
def constraints(draw):
    rd = draw(st.sampled_from(tuple(_VALUES)))
    cmp = draw(st.sampled_from(("gt", "ge", "lt", "le", "approx", "max", "min")))
    if cmp in ("max", "min"):
        return SensorConstraint(rd, cmp)
    return SensorConstraint(rd, cmp, draw(_VALUES[rd]))


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    prefix, tail, written = H.render_sensor_dev8(np.random.default_rng(seed), c)
    text = (prefix + " " + tail).strip()
    assert bool(prefix) != bool(tail)
    assert written.reading == c.reading and written.comparator == c.comparator
    assert read_reading(text) == c.reading, text
    if c.is_superlative:
        assert written.value is None and read_superlative(text) == c.comparator, text
        assert read_numbers(text) == []
        return
    assert written.value == pytest.approx(c.value)
    assert read_numbers(text) == [pytest.approx(written.value)], text
    assert read_comparator(text) == c.comparator, text
    assert read_unit(text) == written.unit, text
    if c.reading == "ndvi":
        assert written.unit == ""


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = H.render_sensor_dev8(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = H.render_goal_dev8(rng, sg, prefix=prefix, tail=tail)
    assert _has(text, sg.target.head)
    if prefix:  # a superlative adjective stands right before the noun phrase
        assert f"{prefix} " in text and text.index(prefix) < text.index(sg.target.head)
    else:
        core = tail.split(" ", 1)[1]
        assert core in text and text.index(sg.target.head) < text.index(core)


def test_number_formats_vary():
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(400):
        _, tail, _ = H.render_sensor_dev8(rng, SensorConstraint("temperature_c", "lt", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "decimal" if "-18.0" in tail else "digits")
    assert seen == {"words", "minus", "decimal", "digits"}
    assert H.number_words(42) == "forty-two" and H.number_words(-7) == "minus seven" and H.number_words(0) == "zero"


# ----------------------------------------------------------------------------------------------------
# Coordinates


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       short=st.booleans(), seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, short, seed):
    xs, ys = (f"{v:g}" if short else f"{v:.1f}" for v in (x + 0.0, y + 0.0))
    hint = H.hint_text_dev8(np.random.default_rng(seed), xs, ys)
    assert [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", hint)] == [float(xs), float(ys)], hint
    text = H.render_goal_dev8(np.random.default_rng(seed), Subgoal(0, Target("guitar", "guitar"),
                                                                       location=Location(x, y)), hint=hint)
    assert text.startswith("the guitar ") and hint in text


# ----------------------------------------------------------------------------------------------------
# Whole instructions: strict and free read differently, goals stay in visiting order

STRICT_CUES = r"\bfirst\b|\bthen\b|in that order|that order|after that|step 1|\b1\)|→|lastly|last of all|" \
              r"before that|in order:|to finish|to begin with|to start with|\blast\b"
FREE_CUES = r"any order|order doesn'?t matter|idc which one first|\bidc\b|not fussy|no difference|whichever order|" \
            r"whatever order|order not important|order up to you|doesn'?t matter which first"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [H.render_goal_dev8(rng, sg) for sg in sgs]
    order = "strict" if strict or len(res) == 1 else "free"
    text = H.render_instruction_dev8(rng, res, order)
    low = text.lower()
    assert text.strip() == text and text
    if len(res) > 1:
        has_free = bool(re.search(FREE_CUES, low))
        has_strict = bool(re.search(STRICT_CUES, re.sub(FREE_CUES, " ", low)))  # "doesnt matter which first"
        assert (has_strict, has_free) == ((True, False) if order == "strict" else (False, True)), text
    # every goal is written whole; in visiting order, except 'B. but before that A'
    written = res[::-1] if "before that" in low else res
    if "before that" in low:
        assert len(res) == 2 and order == "strict"
    at = 0
    for r in written:  # each goal found after the one before it
        at = low.find(r.lower(), at)
        assert at >= 0, (r, text)
        at += len(r)
