"""Set AG's own wording (ragnav_jax/language/phrasings_ag.py), read back by a small reader built from set AG's own
word lists: each rendered goal, sensor phrase, coordinate hint and instruction says what its arguments mean."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ragnav_jax.language import phrasings_ag as ag
from ragnav_jax.language.template_text import hyphenated, number_words
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

HEADS = ("guitar", "toolbox", "credenza", "record player", "snake plant", "shelves", "kiln")
PRE = ("teal", "glossy", "retro", "olive")
STATES = ("switched on", "open", "empty")
ROOMS = ("music room", "pantry", "games room")
REL_TYPES = tuple(ag.REL_WORDS)
SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@st.composite
def targets(draw, depth: int = 2) -> Target:
    head = draw(st.sampled_from(HEADS))
    pre = draw(st.lists(st.sampled_from(PRE), max_size=2, unique=True))
    states = draw(st.lists(st.sampled_from(STATES), max_size=1))
    rels = ()
    if depth:
        rels = tuple(draw(st.lists(st.builds(Relation, st.sampled_from(REL_TYPES), targets(depth - 1)), max_size=2)))
    return Target(" ".join([*pre, head]), head, tuple(pre + states), rels)


subgoals = st.builds(Subgoal, st.just(0), targets(), st.one_of(st.none(), st.sampled_from(ROOMS)))


# ----------------------------------------------------------------------------------------------------
# The reader


def _relation_types(text: str, rooms: tuple[str, ...]) -> list[str]:
    """Relation kinds in the text, read by the longest AG relation phrase starting at each word before 'the'."""
    for room in rooms:
        for f in ag.ROOM_FRAMES:
            text = text.replace(f.format(room), " ")
    phrases = sorted(((w, k) for k, ws in ag.REL_WORDS.items() for w in ws), key=lambda p: -len(p[0]))
    found, i = [], 0
    while i < len(text):
        if i == 0 or text[i - 1] in " (,":
            for w, k in phrases:
                if text.startswith(w + " the ", i):
                    found.append(k)
                    i += len(w)
                    break
        i += 1
    return found


def _all(t: Target):
    yield t
    for r in t.relations:
        yield from _all(r.anchor)


def _rel_kinds(t: Target) -> list[str]:
    return sorted(r.type for x in _all(t) for r in x.relations)


_WORDS = sorted(((number_words(n), n) for n in range(-100, 1000)), key=lambda p: -len(p[0]))


def _value(text: str) -> float:
    half = 0.5 if "and a half" in text else 0.0
    for w, n in _WORDS:
        if re.search(rf"(?<![\w-]){w}(?![\w-])", text):
            return n + half
    m = re.search(r"-?\d*\.?\d+", text)
    return float(m.group()) + half


def read_sensor(prefix: str, tail: str) -> SensorConstraint:
    if prefix:
        rd, cmp = next(k for k, v in ag.SUPER_ADJ.items() if prefix in v)
        return SensorConstraint(rd, cmp, None, "")
    names = sorted(((n, r) for r, ns in ag.NAMES.items() for n in ns), key=lambda p: -len(p[0]))
    rd = next(r for n, r in names if n in tail)
    if any(w in tail for w in ("highest", "comes top", "beats")):
        return SensorConstraint(rd, "max", None, "")
    if any(w in tail for w in ("lowest", "comes bottom", "lower than all")):
        return SensorConstraint(rd, "min", None, "")
    words = sorted(((w.replace("{}", "").strip(), k) for k, ws in ag.CMP_WORDS.items() for w in ws), key=lambda p: -len(p[0]))
    cmp = next(k for w, k in words if w in tail)
    unit = "f" if ("°F" in tail or "Fahrenheit" in tail or "deg F" in tail) else (
        "c" if re.search(r"°C|Celsius|centigrade|degrees C|deg C", tail) else ("%" if re.search(r"%|per ?cent", tail) else ""))
    v = _value(tail)
    if unit == "f":
        v = (v - 32) * 5 / 9
    return SensorConstraint(rd, cmp, v, unit)


STRICT_MARKS = ("in the order", "in order", "sequence", "this order", "same order", "as numbered")
FREE_MARKS = ("any order", "whatever order", "no particular", "whichever", "own order", "order's up to", "no fixed",
              "no set sequence")


def read_order(text: str) -> str | None:
    low = text.lower()
    if any(m in low for m in FREE_MARKS):
        return "free"
    if any(m in low for m in STRICT_MARKS):
        return "strict"
    return None


# ----------------------------------------------------------------------------------------------------
# Tests


@SETTINGS
@given(sg=subgoals, seed=st.integers(0, 2**31))
def test_goal_says_head_attributes_room_and_relations(sg, seed):
    text = ag.render_goal_ag(np.random.default_rng(seed), sg)
    assert text == ag.render_goal_ag(np.random.default_rng(seed), sg)
    for t in _all(sg.target):
        assert t.head in text
        for a in t.attributes:
            assert a in text or hyphenated([a]) in text, (a, text)
    if sg.room:
        assert sg.room in text
    assert sorted(_relation_types(text, (sg.room,) if sg.room else ())) == _rel_kinds(sg.target), text


readings = st.sampled_from(("temperature_c", "humidity_pct", "ndvi"))


@st.composite
def constraints(draw) -> SensorConstraint:
    rd = draw(readings)
    cmp = draw(st.sampled_from(("lt", "le", "gt", "ge", "approx", "max", "min")))
    if cmp in ("max", "min"):
        return SensorConstraint(rd, cmp)
    if rd == "ndvi":
        v = draw(st.integers(5, 95)) / 100
    elif rd == "humidity_pct":
        v = float(draw(st.integers(20, 95)))
    else:
        v = draw(st.integers(-50, 400)) / 2
    return SensorConstraint(rd, cmp, v)


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_says_reading_comparison_and_value(c, seed):
    prefix, tail, written = ag.render_sensor_ag(np.random.default_rng(seed), c)
    assert (prefix, tail, written) == ag.render_sensor_ag(np.random.default_rng(seed), c)
    assert bool(prefix) != bool(tail)
    assert (written.reading, written.comparator, written.value) == (c.reading, c.comparator, c.value)
    got = read_sensor(prefix, tail)
    assert (got.reading, got.comparator, got.unit) == (c.reading, c.comparator, written.unit), (prefix, tail)
    if c.value is not None:
        assert abs(got.value - c.value) < 1e-6, tail


@SETTINGS
@given(sg=subgoals, c=constraints(), seed=st.integers(0, 2**31))
def test_goal_carries_sensor_words_and_hint_numbers_last(sg, c, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = ag.render_sensor_ag(rng, c)
    text = ag.render_goal_ag(rng, sg, prefix=prefix, tail=tail)
    assert (prefix or tail) in text and sg.target.head in text
    bare = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), sg.room)
    hint = ag.hint_text_ag(rng, "3.5", "-2")
    text = ag.render_goal_ag(rng, bare, hint=hint)
    assert hint in text and [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)][-2:] == [3.5, -2.0]


@SETTINGS
@given(x=st.integers(-99, 99), y=st.integers(-99, 99), tenths=st.booleans(), seed=st.integers(0, 2**31))
def test_hint_says_x_then_y(x, y, tenths, seed):
    xs, ys = (f"{v / 10:.1f}" if tenths else str(v) for v in (x, y))
    text = ag.hint_text_ag(np.random.default_rng(seed), xs, ys)
    nums = re.findall(r"-?\d+(?:\.\d+)?", text)
    assert nums[-2:] == [xs, ys] and "x" in text and "y" in text, text


@SETTINGS
@given(n=st.integers(1, 5), strict=st.booleans(), seed=st.integers(0, 2**31))
def test_instruction_keeps_goals_in_order_and_says_the_order(n, strict, seed):
    res = [f"the {h} in the pantry" for h in HEADS[:n]]
    if n > 2:
        res[1] = "the teal guitar (glossy, retro)"
    order = "strict" if strict else "free"
    text = ag.render_instruction_ag(np.random.default_rng(seed), res, order)
    assert text == ag.render_instruction_ag(np.random.default_rng(seed), res, order)
    low = text.lower()
    pos = [low.index(r.lower()) for r in res]
    assert pos == sorted(pos) and all(low.count(r.lower()) == 1 for r in res), text
    assert read_order(text) == (None if n == 1 else order), text


def test_every_instruction_template_is_marked():
    for voice in ag.VOICES:
        for frame, _ in ag.STRICT[voice]:
            assert read_order(frame) == "strict", frame
        for frame, _ in ag.FREE[voice]:
            assert read_order(frame) == "free", frame
        for frame in ag.SINGLE[voice]:
            assert read_order(frame) is None, frame
