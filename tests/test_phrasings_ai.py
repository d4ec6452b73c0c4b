"""Set AI's own wording (ragnav_jax/language/phrasings_ai.py), checked with a tiny reader of that wording written
here: every relation kind, nested anchors, states, attributes, rooms, each sensor reading and comparison with its exact
value (and unit conversions), coordinate hints x then y, and the order statement of strict and free instructions."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_ai as A
from ragnav_jax.language.template_text import number_words
from ragnav_jax.language.types import COMPARATORS, READINGS, RELATION_TYPES, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# ----------------------------------------------------------------------------------------------------
# A small reader of set AI's wording (its own tables, not the module's)

REL_WORDS = {
    "near": "near|close to|not far from|in the neighbourhood of",
    "next_to": "next to|right next to|alongside|immediately next to",
    "beside": "beside|just beside|at the side of",
    "by": "by|over by|down by|standing by",
    "on": "on|on top of|sitting on|resting on",
    "under": "under|underneath|beneath|tucked under",
    "above": "above|up above|directly above|mounted above",
    "in": "inside|in|stowed inside|kept in",
    "with": "with|complete with",
    "in_room_with": "in the same room as|in the room with|sharing a room with|in whichever room holds",
    "in_front_of": "in front of|just in front of|right in front of",
    "behind": "behind|round the back of|tucked behind|just behind",
    "opposite": "opposite|across from|facing|directly opposite",
    "left_of": "to the left of|left of|on the left-hand side of|just left of",
    "right_of": "to the right of|on the right-hand side of|just right of|off to the right of",
}
REL_OF = {w: k for k, ws in REL_WORDS.items() for w in ws.split("|")}
NAME_OF = {"temperature": "temperature_c", "ndvi": "ndvi", "humidity": "humidity_pct", "co2": "co2_ppm",
           "carbon dioxide": "co2_ppm", "noise": "noise_db", "sound level": "noise_db", "light level": "light_lux",
           "illuminance": "light_lux", "battery": "battery_pct", "power": "power_w", "weight": "weight_kg",
           "pressure": "pressure_hpa"}
ADJ_OF = {"warmest": ("temperature_c", "max"), "hottest": ("temperature_c", "max"), "coldest": ("temperature_c", "min"),
          "coolest": ("temperature_c", "min"), "most humid": ("humidity_pct", "max"),
          "dampest": ("humidity_pct", "max"),
          "driest": ("humidity_pct", "min"), "least humid": ("humidity_pct", "min"), "loudest": ("noise_db", "max"),
          "noisiest": ("noise_db", "max"), "quietest": ("noise_db", "min"), "brightest": ("light_lux", "max"),
          "best-lit": ("light_lux", "max"), "dimmest": ("light_lux", "min"), "darkest": ("light_lux", "min"),
          "heaviest": ("weight_kg", "max"), "most power-hungry": ("power_w", "max"),
          "least power-hungry": ("power_w", "min")}
# checked in this order: the negated and longer cues before the bare ones they contain
CMP_CUES = (("approx", r"about|around|roughly|or thereabouts|in the region of"),
            ("ge", r"at least|or more|no lower than|not below|no less than"),
            ("le", r"at most|or less|no higher than|not above|no more than"),
            ("gt", r"above|over|higher than|in excess of|more than"),
            ("lt", r"below|lower than|less than"))
WORDS = sorted(((number_words(n), n) for n in range(1000)), key=lambda p: -len(p[0]))
STRICT = ("no jumping drops", "in that order", "don't re-sequence", "steps are sequential",
          "no deviation from sequence",
          "sequence is critical", "don't skip ahead", "never out of sequence", "order's fixed", "no swapping counts",
          "same order every time", "in sequence")
FREE = ("however suits you", "your call on the routing", "entirely up to you", "not critical",
        "no bearing on the result",
        "any order", "no set order", "whichever you see first", "yours to choreograph", "whatever order")


def read_reading(text: str) -> str:
    low = text.lower()
    hits = {r for name, r in NAME_OF.items() if name in low}
    assert len(hits) == 1, text
    return hits.pop()


def read_sensor(prefix: str, tail: str) -> SensorConstraint:
    if prefix:
        return SensorConstraint(*ADJ_OF[prefix])
    low = tail.lower()
    if re.search(r"\b(highest|biggest)\b", low):
        return SensorConstraint(read_reading(tail), "max")
    if re.search(r"\b(lowest|smallest)\b", low):
        return SensorConstraint(read_reading(tail), "min")
    body = low.replace("co2", "co_").replace("degrees below zero", "degrees bzmark")
    cmp = next(c for c, cues in CMP_CUES if re.search(rf"\b({cues})\b", body))
    m = re.search(r"-?\d+(?:\.\d+)?", body)
    if m:
        v, rest = float(m.group()), body[m.end():]
    else:
        w, v = next((w, n) for w, n in WORDS if f" {w} " in f" {body} ")
        rest = body[body.index(w) + len(w):]
    rest = rest.strip()
    if rest.startswith("degrees bzmark"):
        v = -v
    elif rest.startswith(("°f", "degrees fahrenheit")):
        v = (v - 32) * 5 / 9
    elif rest.startswith(("kw", "kilowatts")):
        v *= 1000
    elif re.match(r"(g|grams)\b", rest):
        v /= 1000
    return SensorConstraint(read_reading(tail), cmp, v)


def read_order(text: str) -> str:
    low = text.lower()
    s, f = any(c in low for c in STRICT), any(c in low for c in FREE)
    assert not (s and f), text
    return "strict" if s else "free" if f else "none"


def _goal(seed: int, sg: Subgoal, **kw) -> str:
    return A.render_goal_ai(np.random.default_rng(seed), sg, **kw)


LAMP, SOFA = Target("lamp", "lamp"), Target("sofa", "sofa")

# ----------------------------------------------------------------------------------------------------
# Goals


def test_reader_tables_are_unambiguous():
    assert set(REL_WORDS) == set(RELATION_TYPES)
    assert len(REL_OF) == sum(len(ws.split("|")) for ws in REL_WORDS.values())


@pytest.mark.parametrize("kind", RELATION_TYPES)
def test_each_relation_kind_is_written_with_its_own_words(kind):
    sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(kind, SOFA),)))
    for seed in range(12):
        text = _goal(seed, sg)
        m = re.fullmatch(r"the lamp (.+) the sofa", text)
        assert m and REL_OF[m.group(1)] == kind, text


def test_nested_anchors_sit_in_brackets_and_later_relations_belong_to_the_target():
    rug = Target("red rug", "rug", ("red",))
    sofa = Target("sofa", "sofa", (), (Relation("on", rug),))
    sg = Subgoal(0, Target("lamp", "lamp", (), (Relation("near", sofa), Relation("behind", Target("desk", "desk")))))
    for seed in range(12):
        text = _goal(seed, sg)
        m = re.fullmatch(r"the lamp (.+) the sofa \((?:the one|itself) (.+) the red rug\) and (?:also )?(.+) the desk",
                         text)
        assert m, text
        assert [REL_OF[g] for g in m.groups()] == ["near", "on", "behind"], text


@given(seed=st.integers(0, 2**31), state=st.sampled_from(["switched on", "open", "empty"]),
       room=st.sampled_from(["kitchen", "living room", "nursery"]))
@SETTINGS
def test_attributes_states_and_room_are_all_written(seed, state, room):
    t = Target("teal wool lamp", "lamp", ("teal", "wool", state))
    text = _goal(seed, Subgoal(0, t, room=room))
    assert "lamp" in text and "teal" in text and "wool" in text and room in text
    assert state in text or state.replace(" ", "-") in text


@given(seed=st.integers(0, 2**31), x=st.floats(-50, 50).map(lambda v: f"{round(v, 2):g}"),
       y=st.floats(-50, 50).map(lambda v: f"{round(v, 2):g}"))
@SETTINGS
def test_a_hint_writes_x_then_y_and_comes_before_relations(seed, x, y):
    rng = np.random.default_rng(seed)
    sg = Subgoal(0, Target("lamp", "lamp", (), (Relation("next_to", SOFA),)), room="study")
    text = A.render_goal_ai(rng, sg, hint=A.hint_text_ai(rng, x, y))
    assert re.findall(r"-?\d+(?:\.\d+)?", text)[-2:] == [x, y], text
    assert text.index(y) < text.index("sofa") and "\u2212" not in text


# ----------------------------------------------------------------------------------------------------
# Sensors

VALUES = st.one_of(st.integers(-30, 5000).map(float), st.sampled_from([0.25, 0.65, 22.5, 1013.25, 1500.0, 0.5, 20.0]))


@given(seed=st.integers(0, 2**31), reading=st.sampled_from(READINGS),
       cmp=st.sampled_from([c for c in COMPARATORS if c not in ("max", "min")]), value=VALUES)
@SETTINGS
def test_thresholds_are_read_back_exactly(seed, reading, cmp, value):
    c = SensorConstraint(reading, cmp, value)
    prefix, tail, written = A.render_sensor_ai(np.random.default_rng(seed), c)
    assert prefix == "" and (written.reading, written.comparator, written.value) == (reading, cmp, value)
    got = read_sensor(prefix, tail)
    assert (got.reading, got.comparator) == (reading, cmp) and got.value == pytest.approx(value, abs=1e-9), tail


@pytest.mark.parametrize("reading", READINGS)
@pytest.mark.parametrize("cmp", ["max", "min"])
def test_superlatives_are_read_back(reading, cmp):
    for seed in range(10):
        prefix, tail, written = A.render_sensor_ai(np.random.default_rng(seed), SensorConstraint(reading, cmp))
        assert written == SensorConstraint(reading, cmp, None, "") and bool(prefix) != bool(tail)
        assert read_sensor(prefix, tail) == SensorConstraint(reading, cmp), (prefix, tail)
        text = _goal(seed, Subgoal(0, LAMP, room="pantry"), prefix=prefix, tail=tail)
        assert "lamp" in text and "pantry" in text and (prefix or tail) in text
        if tail:  # the room comes before a superlative tail
            assert text.index("pantry") < text.index(tail)


def test_unit_changes_keep_the_value():
    seen = set()
    for seed in range(200):
        for c in (SensorConstraint("temperature_c", "ge", 20.0), SensorConstraint("power_w", "lt", 1500.0),
                  SensorConstraint("weight_kg", "approx", 0.25), SensorConstraint("temperature_c", "le", -5.0)):
            _, tail, written = A.render_sensor_ai(np.random.default_rng(seed), c)
            seen.add(written.unit)
            assert read_sensor("", tail).value == pytest.approx(c.value), tail
    assert {"f", "c", "kw", "w", "g", "kg"} <= seen


# ----------------------------------------------------------------------------------------------------
# Whole instructions

GOALS = ["the lamp", "the sofa", "the bed", "the oven"]


@given(seed=st.integers(0, 2**31), n=st.integers(1, 4), strict=st.booleans())
@SETTINGS
def test_order_statement_and_goals_in_order(seed, n, strict):
    res = GOALS[:n]
    text = A.render_instruction_ai(np.random.default_rng(seed), res, "strict" if strict else "free")
    low = text.lower()
    assert [low.index(g) for g in res] == sorted(low.index(g) for g in res)
    if n == 1:
        assert read_order(text) == "none" and not re.search(r"\d", text), text
    else:
        assert read_order(text) == ("strict" if strict else "free"), text


def test_every_voice_is_used():
    openings = {A.render_instruction_ai(np.random.default_rng(s), GOALS[:3], "free").split()[0] for s in range(80)}
    assert len(openings) >= 8


@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans())
@SETTINGS
def test_goals_stand_verbatim_and_same_seed_same_text(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [A.render_goal_ai(rng, sg, hint=A.hint_text_ai(rng, "3.5", "-2")) for sg in sgs]
        return res, A.render_instruction_ai(rng, res, "strict" if strict else "free")

    (res, text), again = run(), run()
    assert (res, text) == again
    for sg, g in zip(sgs, res):
        assert sg.target.head in g and g.lower() in text.lower()
        assert re.findall(r"-?\d+(?:\.\d+)?", g)[-2:] == ["3.5", "-2"] or any(c.isdigit() for c in sg.target.phrase)
