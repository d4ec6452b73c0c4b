"""Held-out set AK's own wording (ragnav_jax/language/phrasings_ak.py): every goal keeps its pieces, instructions
carry each goal once and in order, the three kinds of order framing are told apart, sensor values and coordinate
hints come back exactly, and the same seed writes the same text."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.phrasings_ak import hint_text_ak, render_goal_ak, render_instruction_ak, render_sensor_ak
from ragnav_jax.language.template_text import number_words
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])

STRICT_CUES = ("script order", "strictly in sequence", "story order", "in the order in which they are set",
               "in the order printed", "route order", "every split in order", "in the order i've written",
               "in this order", "keep to that order")
FREE_CUES = ("out of sequence", "entirely flexible", "any order", "whichever order", "left entirely to you",
             "any%", "however you like", "whichever you fancy", "don't mind what order")
VOICES = {"director": ("call sheet", "shot list", "shooting schedule", "one-shot day"),
          "examiner": ("paper", "examination"),
          "speedrunner": ("chat",),
          "nan": ("nan",)}

LAMP = Subgoal(0, Target("teal wool lamp", "lamp", ("teal", "wool", "switched on")), room="nursery")
DRUMS = Subgoal(0, Target("drums", "drums", ("open",), (
    Relation("next_to", Target("credenza", "credenza", (),
                               (Relation("with", Target("record player", "record player")),))),
    Relation("under", Target("king-size shelves", "shelves", ("king-size", "closed"))))))
SOFA = Subgoal(0, Target("grey sofa", "sofa", ("grey",)), room="living room")


def _has(text: str, phrase: str) -> bool:
    return phrase.lower() in text.lower()


def _cues(text: str) -> tuple[bool, bool]:
    low = text.lower()
    return any(c in low for c in STRICT_CUES), any(c in low for c in FREE_CUES)


def _voice(text: str) -> str:
    low = text.lower()
    found = [v for v, marks in VOICES.items() if any(m in low for m in marks)]
    assert len(found) == 1, text
    return found[0]


def _targets(t: Target):
    yield t
    for r in t.relations:
        yield from _targets(r.anchor)


def test_split_is_wired():
    assert "unseen_ak" in EPISODE_SPLITS and EPISODE_SPLITS.index("unseen_ak") == EPISODE_SPLITS.index("unseen_aj") + 1
    assert EPISODE_SPLITS[-1] == "unseen" and UNSEEN_TEMPLATES["unseen_ak"] == ("phrasings_ak", "ak")
    assert _renderer("unseen_ak", "goal") is render_goal_ak and _renderer("unseen_ak", "hint") is hint_text_ak
    assert _renderer("unseen_ak", "sensor") is render_sensor_ak
    assert _renderer("unseen_ak", "instruction") is render_instruction_ak


def test_small_goals_keep_every_piece():
    for seed in range(30):
        rng = np.random.default_rng(seed)
        lamp, drums = render_goal_ak(rng, LAMP), render_goal_ak(rng, DRUMS)
        assert all(_has(lamp, w) for w in ("lamp", "teal", "wool", "nursery")), lamp
        assert "switched on" in lamp or "switched-on" in lamp, lamp
        assert lamp.startswith("the ") and drums.startswith("the ") and "drums" in drums, (lamp, drums)
        for w in ("credenza", "record player", "king-size", "shelves", "open"):
            assert _has(drums, w), drums
        # the credenza's own relation sits in brackets right after it; the shelves come after the bracket
        assert re.search(r"credenza \([^()]*record player\)", drums), drums
        assert drums.index("record player") < drums.index("shelves"), drums


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = render_goal_ak(np.random.default_rng(seed), sg)
    assert text == text.strip(" ,") and text.lower().startswith("the "), text
    for t in _targets(sg.target):
        assert t.head in text, text
        for a in t.attributes:
            assert a in text or a.replace(" ", "-") in text, (a, text)
    if sg.room:
        assert sg.room in text, text
    assert not re.search(r"\d", text) and text.count("(") == text.count(")"), text


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_instruction_keeps_goals_in_order_and_frames_the_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [render_goal_ak(rng, sg) for sg in sgs]
    text = render_instruction_ak(rng, res, "strict" if strict else "free")
    low, at = text.lower(), 0
    for sg, g in zip(sgs, res):
        assert sg.target.head in low
        at = low.index(g.lower(), at) + len(g)  # each goal, as rendered, after the one before it
    is_strict, is_free = _cues(text)
    if len(res) == 1:
        assert not is_strict and not is_free and not re.search(r"\d", text), text
    else:
        assert (is_strict, is_free) == (strict, not strict), text
    _voice(text)


def test_all_four_voices_and_three_framings_turn_up():
    seen = set()
    goals = ["the grey sofa in the living room", "the nursery's teal lamp", "the drums left open"]
    for seed in range(80):
        for n, order in ((1, "strict"), (3, "strict"), (3, "free")):
            text = render_instruction_ak(np.random.default_rng(seed), goals[:n], order)
            seen.add((_voice(text), n, order))
            if n == 1:
                assert not any(_cues(text)) and not re.search(r"\d", text)
    assert {v for v, _, _ in seen} == set(VOICES)
    assert len(seen) == 12


def test_same_seed_same_text():
    def run(seed):
        rng = np.random.default_rng(seed)
        res = [render_goal_ak(rng, sg, hint=hint_text_ak(rng, "1.5", "-4")) for sg in (LAMP, DRUMS, SOFA)]
        return res, render_sensor_ak(rng, SensorConstraint("ndvi", "ge", 0.6)), render_instruction_ak(rng, res, "free")

    assert all(run(s) == run(s) for s in range(10))
    assert len({str(run(s)) for s in range(10)}) > 5


_WORDS = {number_words(n): float(n) for n in range(101)}


def read_value(text: str) -> float:
    """The one number a threshold phrase writes: digits, words or 'N and a half' ('below zero' negates)."""
    m = re.search(r"(-?\d+(?:\.\d+)?)( and a half)?", text)
    if m:
        v = float(m.group(1)) + (0.5 if m.group(2) else 0.0)
    else:
        found = [w for w in _WORDS if re.search(rf"\b{re.escape(w)}\b", text)]
        v = _WORDS[max(found, key=len)]
    return -v if "below zero" in text else v


def canonical(x: float, unit: str) -> float:
    return {"f": lambda: (x - 32) * 5 / 9, "kw": lambda: x * 1000, "g": lambda: x / 1000}.get(unit, lambda: x)()


VALUES = (40.0, 0.65, 22.5, -5.0, 1500.0, 0.25, 1013.0, 7.0, 100.0, 55.5)


@SETTINGS
@given(reading=st.sampled_from(("temperature_c", "ndvi", "humidity_pct", "co2_ppm", "noise_db", "light_lux",
                                "battery_pct", "power_w", "weight_kg", "pressure_hpa")),
       cmp=st.sampled_from(("gt", "ge", "lt", "le", "approx")), value=st.sampled_from(VALUES),
       seed=st.integers(0, 2**31))
def test_sensor_values_come_back_exactly(reading, cmp, value, seed):
    c = SensorConstraint(reading, cmp, value)
    prefix, tail, written = render_sensor_ak(np.random.default_rng(seed), c)
    assert prefix == "" and tail and (written.reading, written.comparator, written.value) == (reading, cmp, value)
    assert canonical(read_value(tail), written.unit) == value, (tail, written)


def test_superlatives_are_an_adjective_or_a_tail():
    for reading in ("temperature_c", "ndvi", "noise_db", "battery_pct", "weight_kg"):
        for cmp in ("max", "min"):
            for seed in range(6):
                c = SensorConstraint(reading, cmp)
                prefix, tail, written = render_sensor_ak(np.random.default_rng(seed), c)
                assert written == c and bool(prefix) != bool(tail) and not re.search(r"\d", prefix + tail)
                goal = render_goal_ak(np.random.default_rng(seed), SOFA, prefix=prefix, tail=tail)
                assert goal.index("living room") < goal.index(tail) if tail else goal.index(prefix) < goal.index("sofa")


def test_a_fahrenheit_or_kilowatt_value_is_exact():
    units = set()
    for seed in range(60):
        for c in (SensorConstraint("temperature_c", "ge", 40.0), SensorConstraint("power_w", "lt", 1500.0),
                  SensorConstraint("weight_kg", "approx", 0.25)):
            _, tail, w = render_sensor_ak(np.random.default_rng(seed), c)
            units.add(w.unit)
            assert canonical(read_value(tail), w.unit) == c.value, tail
    assert {"f", "c", "kw", "w", "g", "kg"} <= units


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       sg=subgoals(), seed=st.integers(0, 2**31), sensor=st.booleans())
def test_hint_numbers_are_the_last_two_x_then_y(x, y, sg, seed, sensor):
    rng = np.random.default_rng(seed)
    xs, ys = f"{x:g}", f"{y:g}"
    prefix, tail, _ = render_sensor_ak(rng, SensorConstraint("humidity_pct", "le", 40.0)) if sensor else ("", "", None)
    text = render_goal_ak(rng, Subgoal(0, sg.target, sg.room, Location(x, y)), prefix, tail,
                          hint=hint_text_ak(rng, xs, ys))
    nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)]
    assert nums[-2:] == [x, y], text
    assert sg.target.head in text


@pytest.mark.parametrize("order", ["strict", "free"])
def test_numbered_lists_only_when_there_are_several(order):
    for seed in range(20):
        one = render_instruction_ak(np.random.default_rng(seed), ["the lamp"], order)
        two = render_instruction_ak(np.random.default_rng(seed), ["the lamp", "the sofa"], order)
        assert one.lower().count("the lamp") == 1 and not re.search(r"\d", one)
        assert two.lower().index("the lamp") < two.lower().index("the sofa")
