"""The `unseen_dev9` templates (set E, held out until parser round 12): deterministic, and every piece of the ground truth is written down.

Checked with small readers of their own (symbols and words for comparators, numbers, units, coordinates, order
cues) that share no code with the templates, over random subgoals drawn by hypothesis.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import REL_WORDS, _all_targets, _has, constraints, read_numbers, subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_dev9 as H
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Location, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# E's own words for relations, on top of the dev8 reader's
E_REL_WORDS = {k: v + {"near": ("a little way from", "close by", "vicinity of"), "next_to": ("up against",),
                       "behind": ("round the back of",), "opposite": ("across the room from",), "on": ("on top of", "resting on"), "under": ("below",),
                       "with": ("that's got", "have got", "has got")}.get(k, ()) for k, v in REL_WORDS.items()}


def test_split_is_wired():
    assert "unseen_dev9" in EPISODE_SPLITS and UNSEEN_TEMPLATES["unseen_dev9"] == ("phrasings_dev9", "dev9")
    assert _renderer("unseen_dev9", "goal") is H.render_goal_dev9
    assert _renderer("unseen_dev9", "sensor") is H.render_sensor_dev9
    assert _renderer("unseen_dev9", "hint") is H.hint_text_dev9
    assert _renderer("unseen_dev9", "instruction") is H.render_instruction_dev9


# Determinism: tests/test_episodes_split.py (every split, same seed, same text).


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = H.render_goal_dev9(np.random.default_rng(seed), sg)
    plain = text.replace("-", " ")  # "switched-on" before a noun
    assert text.startswith("the ")
    for t in _all_targets(sg.target):
        assert _has(text, t.head), (t.head, text)
        for a in t.attributes:
            assert _has(text, a) or _has(plain, a), (a, text)
        for r in t.relations:
            assert any(_has(text, w) for w in E_REL_WORDS[r.type]), (r.type, text)
    if sg.room:
        assert _has(text, sg.room) or _has(text, sg.room + "'s"), text
    low = text.lower()
    assert low.find(sg.target.head) <= min((low.find(r.anchor.head) for r in sg.target.relations), default=10**6) or \
        any(sg.target.head in r.anchor.head for r in sg.target.relations)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back


def read_comparator(text: str) -> str:
    t = " " + text.lower() + " "
    if re.search(r"~|≈|\baround\b", t):
        return "approx"
    if re.search(r">=|≥|at or above", t):
        return "ge"
    if re.search(r"<=|≤|at or below", t):
        return "le"
    if re.search(r">|\babove\b|\bover\b", t):
        return "gt"
    if re.search(r"<|\bbelow\b|\bunder\b", t):
        return "lt"
    return "?"


def read_superlative(text: str) -> str:
    t = text.lower()
    if re.search(r"coldest|coolest|lowest|least|unhealthiest|driest", t):
        return "min"
    if re.search(r"warmest|hottest|highest|healthiest|greenest|most humid|dampest", t):
        return "max"
    return "?"


def read_reading(text: str) -> str:
    t = text.lower()
    if "ndvi" in t or "health" in t or "green" in t:
        return "ndvi"
    if "humid" in t or "damp" in t or "dri" in t or "%" in t or "percent" in t:
        return "humidity_pct"
    return "temperature_c"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    prefix, tail, written = H.render_sensor_dev9(np.random.default_rng(seed), c)
    text = (prefix + " " + tail).strip()
    assert bool(prefix) != bool(tail) and written.reading == c.reading and written.comparator == c.comparator
    assert read_reading(text) == c.reading, text
    if c.is_superlative:
        assert written.value is None and read_superlative(text) == c.comparator, text
        assert read_numbers(text.replace(" one", "")) == [], text  # "the hottest one"
        return
    assert written.value == pytest.approx(c.value)
    assert read_numbers(text.replace("ºC", " C").replace("°C", " C")) == [pytest.approx(written.value)], text
    assert read_comparator(text) == c.comparator, text
    unit = "c" if re.search(r"°c|ºc|degree|\bdeg\b|\d ?c\b", text.lower()) else "%" if re.search(r"%|percent", text) else ""
    assert unit == written.unit, text


def test_symbols_and_words_both_occur():
    rng = np.random.default_rng(5)
    tails = [H.render_sensor_dev9(rng, SensorConstraint("temperature_c", "ge", 20.0))[1] for _ in range(200)]
    assert any(">=" in t for t in tails) and any("≥" in t for t in tails) and any("at or above" in t for t in tails)
    assert any("twenty" in t for t in tails) and any("ºC" in t for t in tails)


# ----------------------------------------------------------------------------------------------------
# Coordinates


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    xs, ys = (f"{v:.1f}" for v in (x + 0.0, y + 0.0))
    hint = H.hint_text_dev9(np.random.default_rng(seed), xs, ys)
    assert [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", hint)] == [float(xs), float(ys)], hint
    text = H.render_goal_dev9(np.random.default_rng(seed), Subgoal(0, Target("guitar", "guitar"),
                                                                       location=Location(x, y)), hint=hint)
    assert text.startswith("the guitar ") and hint in text


# ----------------------------------------------------------------------------------------------------
# Whole instructions

STRICT_CUES = r"before anything else|save .* for last|\bbefore\b|order matters|order as listed|in the order given|" \
              r"order: strict|in sequence|^seq:|->|first of all|last of all|^check:|^goto:|^target =|^nav to|^could you " \
              r"nip|^i need you|^there's|^now dear i want"
FREE_CUES = r"no particular order|whatever order|order's up to you|any order|order not important|order: any|" \
            r"^unordered:|doesn't matter which|whichever order"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [H.render_goal_dev9(rng, sg) for sg in sgs]
    order = "strict" if strict or len(res) == 1 else "free"
    text = H.render_instruction_dev9(rng, res, order)
    low = text.lower()
    has_free, has_strict = bool(re.search(FREE_CUES, low)), bool(re.search(STRICT_CUES, low))
    assert (has_strict, has_free) == ((True, False) if order == "strict" else (False, True)), text
    at = 0
    for r in res:  # every goal written whole, in visiting order
        at = low.find(r.lower(), at)
        assert at >= 0, (r, text)
        at += len(r)
