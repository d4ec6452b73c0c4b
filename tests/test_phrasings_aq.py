"""Set AQ's own wording (ragnav_jax/language/phrasings_aq.py): every goal's head noun stands verbatim, sensor
values read back exactly from the text, coordinate hints give x then y, goals appear once each in visiting order,
multi-goal texts say in words whether the order is fixed or free (a single goal says neither), and the same seed
writes the same text."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language.phrasings_aq import (
    FREE_CUES,
    STRICT_CUES,
    VOICES,
    hint_text_aq,
    render_goal_aq,
    render_instruction_aq,
    render_sensor_aq,
)
from ragnav_jax.language.template_text import number_words
from ragnav_jax.language.types import READINGS, Relation, SensorConstraint, Subgoal, Target

FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
ALL_STRICT = tuple(c for v in VOICES for c in STRICT_CUES[v])
ALL_FREE = tuple(c for v in VOICES for c in FREE_CUES[v])
DIGITS = r"-?\d+(?:\.\d+)?"

# number words as set AQ writes them ('minus eighteen', 'forty-two'), longest first so 'forty-two' beats 'forty'
_WORDS = {number_words(n): n for n in range(-99, 100)}
_ALTS = "|".join(sorted(map(re.escape, _WORDS), key=len, reverse=True))
_WORD_RE = re.compile(r"(?<![a-z-])(" + _ALTS + r")(?![a-z-])")

# unit code -> what the text must say
UNIT_TEXT = {"c": ("°C", "Celsius"), "f": ("°F", "Fahrenheit"), "%": ("%", "per cent"), "ppm": ("ppm", "per million"),
             "db": ("dB", "decibels"), "lux": ("lux",), "w": (" W", "watts"), "kw": ("kW",), "kg": ("kg", "kilo"),
             "hpa": ("hPa", "hectopascals")}
CMP_TEXT = {"gt": ("over ", "above ", "more than "), "lt": ("under ", "below ", "less than "),
            "ge": ("at least ", " or more", "no less than "), "le": ("at most ", " or less", "no more than "),
            "approx": ("about ", "roughly ", "around ", " or thereabouts")}


def read_value(text: str) -> float:
    """The one number a sensor phrase writes, in digits or in words."""
    nums = re.findall(DIGITS, text)
    if nums:
        assert len(nums) == 1, text
        return float(nums[0])
    words = _WORD_RE.findall(text)
    assert len(words) == 1, text
    return float(_WORDS[words[0]])


def canonical(n: float, unit: str) -> float:
    return (n - 32) * 5 / 9 if unit == "f" else n * 1000 if unit == "kw" else n


@st.composite
def constraints(draw):
    reading = draw(st.sampled_from(READINGS))
    comparator = draw(st.sampled_from(("lt", "le", "gt", "ge", "approx", "max", "min")))
    if comparator in ("max", "min"):
        return SensorConstraint(reading, comparator)
    value = draw(st.integers(-40, 2500).map(float) | st.integers(-400, 400).map(lambda k: k / 10)
                 | st.integers(0, 100).map(lambda k: k / 100) | st.sampled_from((40.0, 104.0, 1500.0, 2250.0, -18.0)))
    return SensorConstraint(reading, comparator, value)


def _all_heads(t: Target):
    yield t.head
    for r in t.relations:
        yield from _all_heads(r.anchor)


@FAST
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_keeps_every_head_and_the_room(sg, seed):
    text = render_goal_aq(np.random.default_rng(seed), sg)
    assert text.startswith("the ") and not re.search(r"\d", text), text
    for h in _all_heads(sg.target):
        assert re.search(r"(?<![\w-])" + re.escape(h) + r"(?![\w-])", text), (h, text)
    for a in sg.target.attributes:
        assert a in text or a.replace(" ", "-") in text, (a, text)
    if sg.room:
        assert sg.room in text, text


@FAST
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_values_read_back_exactly(c, seed):
    prefix, tail, got = render_sensor_aq(np.random.default_rng(seed), c)
    assert (got.reading, got.comparator, got.value) == (c.reading, c.comparator, c.value)
    text = f"{prefix} {tail}".strip()
    assert text and (prefix == "" or tail == ""), (prefix, tail)
    if c.is_superlative:
        assert got.unit == "" and not re.search(r"\d", text), text
        if tail:
            assert ("highest" if c.comparator == "max" else "lowest") in tail, tail
        return
    assert prefix == ""
    assert canonical(read_value(tail), got.unit) == c.value, (c, tail)
    assert any(w in tail for w in CMP_TEXT[c.comparator]), (c.comparator, tail)
    if got.unit:
        assert any(w in tail for w in UNIT_TEXT[got.unit]), (got.unit, tail)
    else:
        assert c.reading == "ndvi", (c, tail)


def test_units_other_than_the_canonical_one_are_written():
    rng = np.random.default_rng(0)
    units = {render_sensor_aq(rng, SensorConstraint("temperature_c", "ge", 40.0))[2].unit for _ in range(60)}
    assert {"c", "f"} <= units
    units = {render_sensor_aq(rng, SensorConstraint("power_w", "lt", 1500.0))[2].unit for _ in range(60)}
    assert {"w", "kw"} <= units


@FAST
@given(sg=subgoals(), c=constraints(), seed=st.integers(0, 2**31),
       xy=st.tuples(st.integers(-200, 200), st.integers(-200, 200)))
def test_sensor_and_hint_stand_in_the_goal_with_x_then_y_last(sg, c, seed, xy):
    rng = np.random.default_rng(seed)
    x, y = (f"{v / 10:g}" for v in xy)
    prefix, tail, _ = render_sensor_aq(rng, c)
    hint = hint_text_aq(rng, x, y)
    assert [float(v) for v in re.findall(DIGITS, hint)] == [float(x), float(y)], hint
    text = render_goal_aq(rng, sg, prefix=prefix, tail=tail, hint=hint)
    assert sg.target.head in text and hint in text and (prefix or tail) in text, text
    assert [float(v) for v in re.findall(DIGITS, text)][-2:] == [float(x), float(y)], text


def _goals(sgs, seed):
    rng = np.random.default_rng(seed)
    return [render_goal_aq(rng, sg) for sg in sgs]


@FAST
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_goals_once_each_in_order_and_the_order_said_in_words(sgs, seed, strict):
    res = _goals(sgs, seed)
    assume(not any(a != b and a in b for a in res for b in res) and len(set(res)) == len(res))
    text = render_instruction_aq(np.random.default_rng(seed + 1), res, "strict" if strict else "free")
    at = [text.find(g) for g in res]
    assert all(text.count(g) == 1 for g in res) and at == sorted(at) and -1 not in at, text
    frame = text
    for g in res:
        frame = frame.replace(g, " ")
    low = frame.lower()
    said, unsaid = (ALL_STRICT, ALL_FREE) if strict else (ALL_FREE, ALL_STRICT)
    assert any(c in low for c in said) and not any(c in low for c in unsaid), text
    assert not re.search(r"\d", frame), text


@FAST
@given(sg=subgoals(), seed=st.integers(0, 2**31), strict=st.booleans())
def test_a_single_goal_says_no_order_and_adds_no_digit(sg, seed, strict):
    res = _goals([sg], seed)
    text = render_instruction_aq(np.random.default_rng(seed), res, "strict" if strict else "free")
    assert text.count(res[0]) == 1, text
    frame = text.replace(res[0], " ").lower()
    assert not any(c in frame for c in ALL_STRICT + ALL_FREE) and not re.search(r"\d", frame), text


def test_every_voice_and_frame_says_its_order():
    """Over many seeds (every voice and frame is drawn), each strict text holds a strict cue and no free one, each
    free text the reverse, and every voice writes both kinds."""
    seen = set()
    for n in (2, 3, 5):
        res = ["the teal lamp in the nursery", "the drums opposite the sofa", "the cactus at x 3.5, y 2",
               "the warmest mini-fridge", "the shelves that are empty"][:n]
        for seed in range(60):
            for order in ("strict", "free"):
                low = render_instruction_aq(np.random.default_rng(seed), res, order).lower()
                said, unsaid = (STRICT_CUES, FREE_CUES) if order == "strict" else (FREE_CUES, STRICT_CUES)
                voices = {v for v in VOICES if any(c in low for c in said[v])}
                assert voices and not any(c in low for v in VOICES for c in unsaid[v]), low
                seen |= {(v, order) for v in voices}
    assert seen == {(v, o) for v in VOICES for o in ("strict", "free")}


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), c=constraints(), seed=st.integers(0, 2**31),
       strict=st.booleans())
def test_same_seed_same_text(sgs, c, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        p, t, got = render_sensor_aq(rng, c)
        res = [render_goal_aq(rng, sg, prefix=p, tail=t, hint=hint_text_aq(rng, "3.5", "2")) for sg in sgs]
        return res, got, render_instruction_aq(rng, res, "strict" if strict else "free")

    assert run() == run()


def test_seeds_vary_the_text():
    sg = Subgoal(0, Target("teal lamp", "lamp", ("teal", "switched on"), (Relation("near", Target("sofa", "sofa")),)),
                 room="nursery")
    texts = {render_instruction_aq(np.random.default_rng(s), _goals([sg, sg], s), "strict") for s in range(20)}
    assert len(texts) > 5
