"""Set AO's own wording (ragnav_jax/language/phrasings_ao.py): heads intact, every attribute, state, room, relation
anchor and coordinate kept (x before y), sensor values exact, order cues where (and only where) they belong, four
voices reached, and the same seed writing the same text."""

from __future__ import annotations

import re
from decimal import Decimal

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_ao as ao
from ragnav_jax.language.template_text import number_words
from ragnav_jax.language.types import READINGS, Location, SensorConstraint, Subgoal, Target

STRICT = ("strictly in the order", "never out of sequence", "no item before its turn", "exactly the order listed",
          "strict order of precedence", "fixed sequence", "ahead of its turn", "in exactly that order",
          "exactly that boarding order", "out of turn", "no other", "only after", "order is forced")
FREE = ("whatever order", "any order", "no set order", "no order of precedence", "precedence waived",
        "at your discretion", "whichever order", "up to you", "arbitrary", "any permutation", "does not matter")
VOICE_MARKS = {"librarian": r"librar|stacks|call slip", "protocol officer": r"protocol|excellency|delegation",
               "flight attendant": r"cabin crew|ladies and gentlemen", "mathematician": r"∎|\bqed\b"}
# unit as written -> (scale, offset) from the canonical unit: written = value * scale + offset
UNITS = {"f": (Decimal("1.8"), Decimal(32)), "kw": (Decimal("0.001"), Decimal(0)), "g": (Decimal(1000), Decimal(0))}
REL_WORDS = {"near": ("near", "not far from", "within easy reach of"), "next_to": ("next to", "alongside"),
             "beside": ("beside",), "by": ("by",), "on": ("on", "on top of", "resting on"),
             "under": ("under", "beneath", "underneath"), "above": ("above", "over"), "in": ("in", "inside"),
             "with": ("with", "complete with", "that has"),
             "in_room_with": ("in the same room as", "in the room with", "sharing a room with"),
             "in_front_of": ("in front of",), "behind": ("behind",), "opposite": ("opposite", "across from", "facing"),
             "left_of": ("to the left of", "on the left-hand side of"),
             "right_of": ("to the right of", "on the right-hand side of")}
NUM = r"-?\d+(?:\.\d+)?"


def _words(text: str) -> str:
    return " " + re.sub(r"[^a-z0-9\-'.%°₂]+", " ", text.lower()) + " "


def _has(text: str, phrase: str) -> bool:
    return f" {phrase.lower()} " in _words(text) or f" {phrase.lower()} " in _words(text.replace("-", " "))


def _targets(t: Target):
    yield t
    for r in t.relations:
        yield from _targets(r.anchor)


def _goal(seed: int, sg: Subgoal, sensor: SensorConstraint | None = None, xy=("3.5", "2")):
    rng = np.random.default_rng(seed)
    pre, tail = "", ""
    if sensor is not None:
        pre, tail, _ = ao.render_sensor_ao(rng, sensor)
    return ao.render_goal_ao(rng, sg, prefix=pre, tail=tail, hint=ao.hint_text_ao(rng, *xy) if xy else "")


@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(sg=subgoals(), seed=st.integers(0, 2**31), hint=st.booleans(),
       x=st.sampled_from(["3.5", "-1.25", "0", "12"]), y=st.sampled_from(["2", "7.75", "-4.5"]))
def test_goal_keeps_every_constraint(sg, seed, hint, x, y):
    text = _goal(seed, sg, xy=(x, y) if hint else None)
    for t in _targets(sg.target):  # every head, attribute and state, of the goal and of every anchor
        assert _has(text, t.head), (t.head, text)
        for a in t.attributes:
            assert _has(text, a), (a, text)
    if sg.room:
        assert _has(text, sg.room), (sg.room, text)
    for t in _targets(sg.target):  # every relation is said in words of its own type
        for r in t.relations:
            assert any(f" {w} " in f" {text} " for w in REL_WORDS[r.type]), (r.type, text)
    nums = [float(v) for v in re.findall(NUM, text)]
    assert nums == ([float(x), float(y)] if hint else []), text
    if hint:
        assert text.index(x) < text.rindex(y)


def _back(text: str, c: SensorConstraint, out: SensorConstraint) -> bool:
    """The written number (digits or words) converts back to the value exactly."""
    scale, offset = UNITS.get(out.unit, (Decimal(1), Decimal(0)))
    written = Decimal(repr(float(c.value))) * scale + offset
    found = re.findall(NUM, text)
    if found:
        return len(found) == 1 and (Decimal(found[0]) - offset) / scale == Decimal(repr(float(c.value)))
    return written == written.to_integral_value() and _has(text, number_words(int(written)))


def test_sensor_values_round_trip_exactly():
    values = (40.0, 0.65, 22.5, -5.0, 1500.0, 0.375, 1013.25, 7.0)
    seen_units = set()
    for i, (reading, cmp, v) in enumerate((r, c, v) for r in READINGS for c in ao._CMP for v in values):
        c = SensorConstraint(reading, cmp, None if cmp in ("max", "min") else v)
        for seed in range(3):
            pre, tail, out = ao.render_sensor_ao(np.random.default_rng(1000 * i + seed), c)
            text = f"{pre} {tail}"
            assert (out.reading, out.comparator, out.value) == (c.reading, c.comparator, c.value), (c, out)
            assert bool(pre) != bool(tail) and (not pre or c.is_superlative), (pre, tail)
            if c.is_superlative:
                assert not re.search(r"\d", text) and out.unit == ""
            else:
                assert _back(text, c, out), (c, out, text)
                seen_units.add(out.unit)
    assert {"c", "f", "%", "kw", "g", "mbar"} <= seen_units


def test_sensor_sits_in_the_goal_before_the_hint():
    sg = Subgoal(0, Target("teal lamp", "lamp", ("teal",)), room="kitchen")
    for seed in range(40):
        c = SensorConstraint("temperature_c", "ge", 21.5)
        text = _goal(seed, sg, c, xy=("3.5", "2"))
        nums = [float(v) for v in re.findall(NUM, text)]
        assert nums[-2:] == [3.5, 2.0] and _has(text, "lamp") and _has(text, "teal"), text
        assert text.index("kitchen") < text.index("3.5")


GOALS = ["the teal lamp over in the kitchen", "the sofa with an NDVI of about 0.65", "the drums at x 3.5, y 2",
         "the shelves to the left of the appliance"]


def _skeleton(text: str, res: list[str]) -> str:
    for i, r in enumerate(res):
        text = text.replace(r, "<" + "abcd"[i] + ">")
    return text


def _voice(text: str) -> list[str]:
    return [v for v, pat in VOICE_MARKS.items() if re.search(pat, text.lower())]


def test_instructions_cues_voices_and_frames():
    frames = {1: set(), 2: set()}
    voices = set()
    for seed in range(400):
        n = 1 + seed % 4
        res = GOALS[:n]
        for order in ("strict", "free"):
            text = ao.render_instruction_ao(np.random.default_rng(seed), res, order)
            low = text.lower()
            pos = [text.index(r) for r in res]
            assert pos == sorted(pos) and all(text.count(r) == 1 for r in res), text
            strict, free = any(m in low for m in STRICT), any(m in low for m in FREE)
            if n == 1:
                assert not strict and not free and not re.search(r"\d", _skeleton(text, res)), text
                frames[1].add(_skeleton(text, res))
            else:
                assert (strict, free) == (order == "strict", order == "free"), (order, text)
                if n == 2:
                    frames[2].add((order, _skeleton(text, res)))
            v = _voice(text)
            assert len(v) == 1, (v, text)
            voices.add(v[0])
    assert voices == set(ao.VOICES)
    assert len(frames[1]) == 12 and len(frames[2]) == 24, (len(frames[1]), len(frames[2]))


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans())
def test_same_seed_same_text_and_goals_verbatim(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        sgs2 = [Subgoal(i, s.target, s.room, Location(1.5, -2.0)) for i, s in enumerate(sgs)]
        res = [ao.render_goal_ao(rng, s, hint=ao.hint_text_ao(rng, "1.5", "-2")) for s in sgs2]
        return res, ao.render_instruction_ao(rng, res, "strict" if strict else "free")

    res, text = run()
    assert (res, text) == run()
    low = text.lower()
    assert all(r.lower() in low and s.target.head in low for r, s in zip(res, sgs))
