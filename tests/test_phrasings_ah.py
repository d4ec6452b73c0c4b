"""Set AH's own wording (ragnav_jax/language/phrasings_ah.py): every relation kind, state, room, sensor comparison,
superlative and coordinate hint is in the text with its value, and strict / free instructions carry an order cue.
The little readers here know only AH's own words; no reader of the project is imported."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_ah as AH
from ragnav_jax.language.template_text import number_words
from ragnav_jax.language.types import RELATION_TYPES, Location, Relation, SensorConstraint, Subgoal, Target

SEEDS = st.integers(0, 2**31)
FAST = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# AH's words for each relation kind, as a reader of AH alone would list them
CUES = {"near": ("near", "close to", "not far from", "within easy reach of"),
        "next_to": ("next to", "alongside"), "beside": ("beside", "at the side of"), "by": ("by",),
        "on": ("on", "on top of", "sitting on", "resting on"), "under": ("under", "underneath", "beneath"),
        "above": ("above",), "in": ("in", "inside", "kept in"), "with": ("with", "that has", "that comes with"),
        "in_room_with": ("in the same room as", "sharing a room with", "in whichever room holds", "in the room with"),
        "in_front_of": ("in front of",), "behind": ("behind", "round the back of"),
        "opposite": ("opposite", "across from", "facing"),
        "left_of": ("to the left of", "on the left-hand side of", "left of"),
        "right_of": ("to the right of", "on the right-hand side of", "right of")}


def read_relation(text: str, anchor: str) -> str:
    """The relation kind whose longest cue stands right before 'the <anchor>'."""
    before = text[: text.index(f" the {anchor}")]
    hits = [(len(c), kind) for kind, cues in CUES.items() for c in cues if before.endswith(" " + c)]
    return max(hits)[1]


# comparison cues, negated ones first
CMP_CUES = (("not below", "ge"), ("no lower than", "ge"), ("or more", "ge"), ("at least", "ge"),
            ("not above", "le"), ("no higher than", "le"), ("or less", "le"), ("at most", "le"), ("tops out at", "le"),
            ("about", "approx"), ("around", "approx"), ("roughly", "approx"), ("region of", "approx"),
            ("thereabouts", "approx"), ("above", "gt"), ("over", "gt"), ("more than", "gt"), ("higher than", "gt"),
            ("exceeds", "gt"), ("below", "lt"), ("under", "lt"), ("less than", "lt"), ("lower than", "lt"),
            ("short of", "lt"))
READING_CUES = {"temperature_c": ("temp", "thermometer"), "ndvi": ("NDVI",), "humidity_pct": ("humidity",),
                "co2_ppm": ("CO2", "carbon dioxide"), "noise_db": ("noise", "sound", "decibel"),
                "light_lux": ("light", "brightness"), "battery_pct": ("battery", "charge"),
                "power_w": ("power", "wattage"), "weight_kg": ("weight", "mass"), "pressure_hpa": ("pressure",)}


def read_comparator(tail: str) -> str:
    return next(k for cue, k in CMP_CUES if cue in tail)


def spellings(v: float, unit: str) -> list[str]:
    """Every way AH may write value v (canonical unit) given the unit it says it wrote."""
    if unit == "f":
        v = v * 9 / 5 + 32
    if unit == "kw":
        v = v / 1000
    out = [AH._num(v)]
    if float(v).is_integer():
        out.append(number_words(int(v)))
    elif float(v * 2).is_integer() and abs(v) >= 1:
        out.append(number_words(int(v)) + " and a half")
    if v < 0 and unit == "c":
        out += [s + " degrees below zero" for s in spellings(-v, "")]
    return out


def lamp(*rels: Relation, attrs=("teal",), phrase="teal lamp") -> Target:
    return Target(phrase, "lamp", tuple(attrs), tuple(rels))


@FAST
@given(seed=SEEDS, kind=st.sampled_from(RELATION_TYPES))
def test_each_relation_kind_reads_back(seed, kind):
    g = AH.render_goal_ah(np.random.default_rng(seed), Subgoal(0, lamp(Relation(kind, Target("shelves", "shelves")))))
    assert read_relation(g, "shelves") == kind, g


@FAST
@given(seed=SEEDS, outer=st.sampled_from(RELATION_TYPES), inner=st.sampled_from(RELATION_TYPES))
def test_nested_anchor_sits_in_brackets(seed, outer, inner):
    table = Target("oak table", "table", ("oak",), (Relation(inner, Target("window", "window")),))
    g = AH.render_goal_ah(np.random.default_rng(seed), Subgoal(0, lamp(Relation(outer, table))))
    assert "(the one " in g and g.index("table") < g.index("(the one") < g.index("window") and "oak" in g
    assert read_relation(g, "window") == inner
    assert read_relation(g, "oak table" if " the oak table" in g else "table") == outer


@FAST
@given(seed=SEEDS, state=st.sampled_from(["switched on", "open", "empty"]),
       room=st.sampled_from(["kitchen", "living room"]))
def test_attributes_states_and_room_are_all_written(seed, state, room):
    t = lamp(attrs=("teal", "wool", state), phrase="teal wool lamp")
    g = AH.render_goal_ah(np.random.default_rng(seed), Subgoal(0, t, room=room))
    assert "lamp" in g and "teal" in g and "wool" in g and f"the {room}" in g
    assert state in g or state.replace(" ", "-") in g


VALUES = {"temperature_c": (40.0, 22.5, -4.0, 0.0), "ndvi": (0.65, 0.2), "humidity_pct": (40.0, 62.5),
          "co2_ppm": (800.0,), "noise_db": (55.0,), "light_lux": (300.0,), "battery_pct": (20.0,),
          "power_w": (1500.0, 60.0), "weight_kg": (2.5, 12.0), "pressure_hpa": (1013.0, 987.5)}
THRESHOLDS = [(r, c, v) for r, vs in VALUES.items() for v in vs for c in ("lt", "le", "gt", "ge", "approx")]


@pytest.mark.parametrize(("reading", "cmp", "value"), THRESHOLDS)
def test_thresholds_read_back(reading, cmp, value):
    for seed in range(12):
        c = SensorConstraint(reading, cmp, value)
        prefix, tail, written = AH.render_sensor_ah(np.random.default_rng(seed), c)
        assert prefix == "" and (written.reading, written.comparator, written.value) == (reading, cmp, value)
        assert read_comparator(tail) == cmp, tail
        assert any(w in tail for w in READING_CUES[reading]), tail
        assert any(s in tail for s in spellings(value, written.unit)), (tail, written)
        assert written.unit != "f" or "Fahrenheit" in tail
        assert written.unit != "kw" or "kW" in tail or "kilowatts" in tail


@pytest.mark.parametrize("reading", sorted(VALUES))
@pytest.mark.parametrize("cmp", ["max", "min"])
def test_superlatives_read_back(reading, cmp):
    for seed in range(12):
        prefix, tail, written = AH.render_sensor_ah(np.random.default_rng(seed), SensorConstraint(reading, cmp))
        assert written == SensorConstraint(reading, cmp, None, "")
        if prefix:
            assert tail == "" and prefix in AH._SUP_ADJ[(reading, cmp)]
        else:
            assert any(w in tail for w in READING_CUES[reading])
            assert ("high" in tail or "beats" in tail) if cmp == "max" else "low" in tail


NUM = st.floats(-20, 20, allow_nan=False).map(lambda v: round(v, 2))


@FAST
@given(seed=SEEDS, x=NUM, y=NUM, kind=st.sampled_from(RELATION_TYPES))
def test_hint_writes_x_then_y_last(seed, x, y, kind):
    rng = np.random.default_rng(seed)
    hint = AH.hint_text_ah(rng, AH._num(x), AH._num(y))
    sg = Subgoal(0, lamp(Relation(kind, Target("sofa", "sofa"))), room="study", location=Location(x, y))
    g = AH.render_goal_ah(rng, sg, hint=hint)
    assert hint in g and [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", g)][-2:] == [x, y]


STRICT = ("catalogue order, no exceptions", "order printed in the catalogue", "running order is the catalogue order",
          "as the card reads", "in order, no skipping holes", "out of turn", "sequence in order", "just as I call it",
          "only works in the order given", "set in stone", "to the letter")
FREE = ("any order", "however you please", "no running order", "no set order", "order's up to you", "no right order",
        "whatever order", "order doesn't matter", "no fixed order")


@FAST
@given(seed=SEEDS, sgs=st.lists(subgoals(), min_size=1, max_size=5), order=st.sampled_from(["strict", "free"]))
def test_instructions_keep_goals_and_say_the_order(seed, sgs, order):
    rng = np.random.default_rng(seed)
    res = [AH.render_goal_ah(rng, sg) for sg in sgs]
    text = AH.render_instruction_ah(rng, res, order)
    at = 0
    for sg, g in zip(sgs, res):
        assert sg.target.head in g
        at = text.index(g, at) + len(g)
    wrapper = text
    for g in res:
        wrapper = wrapper.replace(g, "")
    strict, free = (any(c.lower() in wrapper.lower() for c in cues) for cues in (STRICT, FREE))
    if len(res) == 1:
        assert not strict and not free and not re.search(r"\d", wrapper)
    else:
        assert (strict, free) == (order == "strict", order == "free"), text


@FAST
@given(seed=SEEDS, sg=subgoals())
def test_same_seed_same_goal(seed, sg):
    def run():
        rng = np.random.default_rng(seed)
        return AH.render_goal_ah(rng, sg), AH.render_instruction_ah(rng, ["the lamp", "the sofa"], "strict")

    assert run() == run()
