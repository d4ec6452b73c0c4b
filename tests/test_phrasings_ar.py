"""Set AR's own wording (ragnav_jax/language/phrasings_ar.py), on tiny inputs: every voice and layout turns up and
says its order in words (strict: fixed, free: open, one goal: neither, no digit in any frame); each goal keeps its
head, room, attributes, states, sensor value and unit and coordinate hint where the style guide puts them; sensor
numbers and hints read back exactly; the same seed writes the same text. The order cues and comparator words are
this file's own reading of the text, written here rather than taken from the module, so that a broken frame
fails here."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_ar as A
from ragnav_jax.language.template_text import both, hyphenated, number_words
from ragnav_jax.language.types import READINGS, Relation, SensorConstraint, Subgoal, Target

STRICT = re.compile(r"set in stone|nobody pads up|in the order i read|exactly as listed|in exactly this order|"
                    r"strictly in|keep to that|stick to that order|the order so declared is final", re.I)
FREE = re.compile(r"batting order's open|no batting order|no set batting order|batting order's up to you|"
                  r"no particular order|any order|doesn't matter what order|whatever order|no order of precedence|"
                  r"left wholly to the robot|no set order", re.I)
SEQUENCE = re.compile(r"\b(first|then|next|after that|lastly|last man|opening up|start with|start on|finish)\b",
                      re.I)
# what parts two goals: a line break, a semicolon, a sentence end or a sequence word; never a bare 'and'
PARTING = re.compile(r"[\n;.]|\b(then|next|after that|finish)\b", re.I)
VOICES = {"cricket captain": r"\blads\b|\bskip\b|batting|team sheet", "studio potter": r"\bRos\b",
          "returning officer": r"Returning Officer", "amateur astronomer": r"Clear skies"}
LAYOUTS = {"dressing-room talk": r"gather round|skipper speaking", "team sheet": r"^TEAM SHEET",
           "kiln-log whiteboard": r"^(KILN LOG|BISQUE LOAD)", "note on the wheel": r"^Morning",
           "published notice": r"hereby give notice", "declaration at the count": r"do hereby declare",
           "observing plan": r"^(Observing plan|Tonight's target list)", "club chat post": r"^(Hi all|Evening all)"}
NUM = re.compile(r"-?\d+(?:\.\d+)?")

SOFA = Target("teal sofa", "sofa", ("teal", "switched on"), (Relation("on", Target("toolbox", "toolbox")),))
DRUMS = Target("drums", "drums", ("empty",))
LAMP = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"),
              (Relation("next_to", SOFA), Relation("behind", DRUMS)))
GOALS = (Subgoal(0, LAMP, room="nursery"), Subgoal(0, Target("shelves", "shelves", ("open",)), room="games room"),
         Subgoal(0, Target("vintage hi-fi speaker", "hi-fi speaker", ("vintage",))),
         Subgoal(0, Target("olive chest freezer", "chest freezer", ("olive", "full")), room="laundry room"))
SENSORS = (SensorConstraint("temperature_c", "ge", 40.0), SensorConstraint("weight_kg", "le", 0.5),
           SensorConstraint("co2_ppm", "max"), SensorConstraint("humidity_pct", "lt", 35.5), None)


def _goals(seed: int, n: int) -> list[str]:
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        c = SENSORS[(seed + i) % len(SENSORS)]
        prefix, tail = ("", "") if c is None else A.render_sensor_ar(rng, c)[:2]
        hint = A.hint_text_ar(rng, "3.5", "2") if (seed + i) % 3 else ""
        out.append(A.render_goal_ar(rng, GOALS[i % len(GOALS)], prefix, tail, hint))
    return out


def _frame_only(text: str, res: list[str]) -> list[str]:
    """The text round the goals, in pieces (before the first, between each pair, after the last); checks every
    goal is written once, in the order given."""
    low, pos, pieces = text.lower(), 0, []
    for g in res:
        assert low.count(g.lower()) == 1, (g, text)
        i = low.find(g.lower(), pos)
        assert i >= 0, ("goal missing or out of order", g, text)
        pieces.append(text[pos:i])
        pos = i + len(g)
    return [*pieces, text[pos:]]


def _check_frame(text: str, res: list[str], order: str, voice: str, layout: str) -> None:
    pieces = _frame_only(text, res)
    frame = " | ".join(pieces)
    assert re.search(VOICES[voice], text, re.I), (voice, text)
    assert re.search(LAYOUTS[layout], text, re.M), (layout, text)
    assert not re.search(r"\d", frame), text
    for between in pieces[1:-1]:
        assert PARTING.search(between), ("goals not parted", between, text)
    if len(res) == 1:
        assert not STRICT.search(frame) and not FREE.search(frame) and not SEQUENCE.search(frame), text
    elif order == "strict":
        assert STRICT.search(frame) and not FREE.search(frame), ("no strict cue", text)
    else:
        assert FREE.search(frame) and not STRICT.search(frame) and not SEQUENCE.search(frame), ("no free cue", text)


@pytest.mark.parametrize("k", range(len(A.FRAMES)))
def test_every_voice_and_frame_says_its_order(k):
    voice, layout, frame = A.FRAMES[k]
    for seed in range(40):
        for n in (1, 2, 3, 4, 5):
            for order in ("strict", "free"):
                res = _goals(seed, n)
                text = frame(np.random.default_rng(seed), res, "single" if n == 1 else order)
                _check_frame(text, res, order, voice, layout)


def test_render_instruction_draws_every_voice_and_layout():
    seen = set()
    for seed in range(400):
        n = 1 + seed % 4
        order = ("strict", "free")[seed // 4 % 2]
        res = _goals(seed, n)
        text = A.render_instruction_ar(np.random.default_rng(seed), res, order)
        hits = [(v, lay) for v, lay, _ in A.FRAMES if re.search(LAYOUTS[lay], text, re.M)]
        assert len(hits) == 1, text
        _check_frame(text, res, order, *hits[0])
        seen.add(hits[0])
    assert seen == {(v, lay) for v, lay, _ in A.FRAMES}


def _state_written(text: str, sg: Subgoal, states: list[str]) -> bool:
    t = sg.target
    if f"{hyphenated(states)} {t.phrase}" in text:
        return True
    room = f" in the {sg.room}" if sg.room and f"the {sg.room}'s" not in text else ""
    after = rf"{re.escape(t.phrase + room)} (that is|that are|which is currently|which are currently|that has been " \
            rf"left|that have been left) {re.escape(both(states))}"
    return re.search(after, text) is not None


def test_goal_carries_everything_in_place():
    for seed in range(150):
        for sg in GOALS:
            for c in SENSORS:
                rng = np.random.default_rng(seed)
                prefix, tail = ("", "") if c is None else A.render_sensor_ar(rng, c)[:2]
                hint = A.hint_text_ar(rng, "3.5", "2")
                text = A.render_goal_ar(rng, sg, prefix, tail, hint)
                t = sg.target
                states = [a for a in t.attributes if a not in t.phrase.split()]
                assert text.startswith("the ") and t.phrase in text, text
                if sg.room:  # straight after the noun, or before it as a possessive that also leads any superlative
                    assert f"{t.phrase} in the {sg.room}" in text or text.startswith(f"the {sg.room}'s "), text
                if prefix:
                    lead = f"the {sg.room}'s " if text.startswith(f"the {sg.room}'s ") else "the "
                    assert text.startswith(lead + prefix + " "), text
                if states:
                    assert _state_written(text, sg, states), text
                end_main = text.index(hint)
                if tail:
                    assert text.index(t.phrase) < text.index(tail) < end_main, text
                assert [float(v) for v in NUM.findall(text)][-2:] == [3.5, 2.0], text
                if t.relations:  # relations last, anchors after the hint, the anchor's own relation in brackets
                    rest = text[end_main + len(hint):]
                    assert "sofa" in rest and "drums" in rest and "toolbox" in rest, text
                    assert re.search(r"switched-on teal sofa \((the one|which is|itself) (on|on top of|sitting on) "
                                     r"the toolbox\)", rest), text
                    assert re.search(r"^, both |, and also | as well as ", rest), text
                    assert re.search(r"the empty drums$", text), text


@pytest.mark.parametrize("xy", [("3.5", "2"), ("-1.25", "7"), ("0", "10.5"), ("12", "-3")])
def test_hint_is_x_then_y_and_last(xy):
    x, y = xy
    for seed in range(60):
        rng = np.random.default_rng(seed)
        h = A.hint_text_ar(rng, x, y)
        assert NUM.findall(h) == [x, y], h
        text = A.render_goal_ar(rng, GOALS[seed % len(GOALS)], *A.render_sensor_ar(rng, SENSORS[seed % 4])[:2], hint=h)
        assert NUM.findall(text)[-2:] == [x, y], text


WORDS = sorted(((number_words(i), i) for i in range(-99, 100)), key=lambda p: -len(p[0]))
BACK = {"f": lambda v: (v - 32) * 5 / 9, "kw": lambda v: v * 1000, "g": lambda v: v / 1000}
UNITS = {"temperature_c": {"c", "f"}, "ndvi": {""}, "humidity_pct": {"%"}, "co2_ppm": {"ppm"}, "noise_db": {"db"},
         "light_lux": {"lux"}, "battery_pct": {"%"}, "power_w": {"w", "kw"}, "weight_kg": {"kg", "g"},
         "pressure_hpa": {"hpa", "mbar"}}
NAMED = {"temperature_c": r"temperature|hotter|cooler", "ndvi": r"NDVI", "humidity_pct": r"humidity",
         "co2_ppm": r"carbon dioxide", "noise_db": r"noise|sound", "light_lux": r"light", "battery_pct": r"battery",
         "power_w": r"power|drawing", "weight_kg": r"weight|weighing", "pressure_hpa": r"air pressure"}
CMP = {"gt": r"above|over|higher than|more than|hotter than", "lt": r"below|under|lower than|less than|cooler than",
       "ge": r"at least|or more|no lower than|or above", "le": r"at most|or less|no higher than|not above|no more than",
       "approx": r"about|roughly|around|close to"}
VALUES = {"temperature_c": (40.0, 22.5, -4.0, 18.3, 0.0), "ndvi": (0.65, 0.2, 1.0), "humidity_pct": (40.0, 35.5),
          "co2_ppm": (800.0, 1250.5, 60.0), "noise_db": (60.0, 42.5), "light_lux": (300.0, 12.0),
          "battery_pct": (20.0, 87.5), "power_w": (1500.0, 60.0, 2200.0, 1234.5), "weight_kg": (0.5, 20.0, 2.25),
          "pressure_hpa": (1013.25, 990.0)}


def _number(tail: str) -> float:
    digits = NUM.findall(tail)
    if digits:
        assert len(digits) == 1, tail
        return float(digits[0])
    for w, i in WORDS:
        if re.search(rf"(?<![\w-]){re.escape(w)}(?![\w-])", tail):
            return float(i)
    raise AssertionError(f"no number in {tail!r}")


def test_sensor_values_read_back_exactly():
    assert set(UNITS) == set(READINGS)
    units_seen = {r: set() for r in READINGS}
    for reading in READINGS:
        for cmp in ("gt", "lt", "ge", "le", "approx"):
            for v in VALUES[reading]:
                for seed in range(30):
                    c = SensorConstraint(reading, cmp, v)
                    prefix, tail, w = A.render_sensor_ar(np.random.default_rng(seed), c)
                    assert prefix == "" and (w.reading, w.comparator, w.value) == (reading, cmp, v), (tail, w)
                    assert w.unit in UNITS[reading], w
                    assert re.search(NAMED[reading], tail) and re.search(CMP[cmp], tail), tail
                    assert "co2" not in tail.lower(), tail
                    assert BACK.get(w.unit, lambda x: x)(_number(tail)) == v, (tail, w)
                    units_seen[reading].add(w.unit)
    assert units_seen == UNITS  # every second unit turns up somewhere


def test_superlatives_carry_no_number_and_keep_the_room_in_scope():
    for reading in READINGS:
        for cmp in ("max", "min"):
            for seed in range(20):
                rng = np.random.default_rng(seed)
                prefix, tail, w = A.render_sensor_ar(rng, SensorConstraint(reading, cmp))
                assert (w.value, w.unit, w.comparator, w.reading) == (None, "", cmp, reading)
                assert bool(prefix) != bool(tail) and not re.search(r"\d", prefix + tail)
                if tail:
                    assert ("highest" if cmp == "max" else "lowest") in tail and re.search(NAMED[reading], tail)
                text = A.render_goal_ar(rng, GOALS[1], prefix, tail)
                if prefix:
                    assert text.startswith(f"the games room's {prefix} ") or text.startswith(f"the {prefix} "), text
                    assert "games room" in text
                else:  # the room comes before the tail
                    assert text.startswith("the games room's ") or text.index("in the games room") < text.index(tail)


def test_same_seed_same_text():
    def run(seed):
        rng = np.random.default_rng(seed)
        res = [A.render_goal_ar(rng, sg, *A.render_sensor_ar(rng, SENSORS[seed % 4])[:2],
                                hint=A.hint_text_ar(rng, "3.5", "2")) for sg in GOALS]
        return res, A.render_instruction_ar(rng, res, "strict" if seed % 2 else "free")

    for seed in range(50):
        assert run(seed) == run(seed)


def _heads(t: Target) -> list[str]:
    return [t.head] + [h for r in t.relations for h in _heads(r.anchor)]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans())
def test_any_goals_keep_heads_hint_and_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [A.render_goal_ar(rng, sg, hint=A.hint_text_ar(rng, "4.25", "1")) for sg in sgs]
    for sg, g in zip(sgs, res):
        assert all(h in g for h in _heads(sg.target)), g
        assert NUM.findall(g) == ["4.25", "1"], g
        assert g.count("(") == g.count(")"), g
        if sg.room:
            assert f"in the {sg.room}" in g or g.startswith(f"the {sg.room}'s "), g
    if len(set(r.lower() for r in res)) < len(res) or any(
            a.lower() in b.lower() for a in res for b in res if a is not b):
        return  # two goals written alike: the order check below cannot tell them apart
    order = "strict" if strict else "free"
    text = A.render_instruction_ar(rng, res, order)
    hits = [(v, lay) for v, lay, _ in A.FRAMES if re.search(LAYOUTS[lay], text, re.M)]
    assert len(hits) == 1, text
    pieces = _frame_only(text, res)
    assert not re.search(r"\d", " ".join(pieces)), text
